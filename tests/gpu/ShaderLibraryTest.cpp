// The shader library and the build's manifest: every program permutation loads, and a
// missing folder, manifest or permutation is an error that says which.
#include "WarpDevice.h"
#include "core/Error.h"

#include <fstream>

namespace firmament::test {
namespace {

TEST_F(WarpDevice, EveryPermutationInTheProgramsManifestCreatesAShader) {
    std::ifstream manifest(productShaders() / "manifest.txt");
    ASSERT_TRUE(manifest) << "no manifest in " << productShaders().string();
    std::string line;
    int loaded = 0;
    while (std::getline(manifest, line)) {
        if (line.rfind("#source\t", 0) == 0 || line.rfind("#cache\t", 0) == 0) continue;  // the HLSL folder and the cache, below
        const std::string id = line.substr(0, line.find('\t'));
        // Split "file|entry|profile|defines" back into a key and load it by that key.
        ShaderKey key;
        size_t start = 0, bar = 0;
        std::string* fields[3] = {&key.file, &key.entry, &key.profile};
        for (auto* field : fields) {
            bar = id.find('|', start);
            *field = id.substr(start, bar - start);
            start = bar + 1;
        }
        const std::string defines = id.substr(start);
        for (size_t at = 0; at < defines.size();) {
            const size_t comma = std::min(defines.find(',', at), defines.size());
            key.defines.push_back(defines.substr(at, comma - at));
            at = comma + 1;
        }
        ASSERT_EQ(key.id(), id);
        EXPECT_FALSE(productShaderLibrary->bytecode(key).empty()) << id;
        ++loaded;
    }
    EXPECT_GE(loaded, 2);
    EXPECT_EQ(productShaderLibrary->size(), static_cast<size_t>(loaded));
    // The manifest names the HLSL folder it was compiled from, which hot reload uses.
    const auto source = PrecompiledShaders(productShaders()).sourceRoot();
    ASSERT_TRUE(source.has_value());
    EXPECT_TRUE(std::filesystem::exists(*source / "postfx" / "tone_mapping.hlsl")) << source->string();
    // A build through cmake/shader-cache.sh names it, for hot reload to use the same cache.
    const std::string launcher = PrecompiledShaders(productShaders()).cacheLauncher();
    if (!launcher.empty()) {
        EXPECT_NE(launcher.find("shader-cache.sh"), std::string::npos) << launcher;
    }
}

TEST_F(WarpDevice, MissingPermutationNamesItsKey) {
    try {
        testShaderLibrary->computeShader({"compute/transmittance.hlsl", "main", "cs_5_0", {"SCALE=7"}});
        FAIL() << "a permutation the build did not make was found";
    } catch (const Error& e) {
        EXPECT_NE(std::string(e.what()).find("compute/transmittance.hlsl|main|cs_5_0|SCALE=7"), std::string::npos) << e.what();
    }
}

TEST(PrecompiledShaders, MissingFolderOrManifestIsAnError) {
    EXPECT_THROW(PrecompiledShaders{executableFolder() / "no-such-shader-folder"}, Error);
    EXPECT_THROW(PrecompiledShaders{executableFolder()}, Error);  // a folder without manifest.txt
}

}  // namespace
}  // namespace firmament::test
