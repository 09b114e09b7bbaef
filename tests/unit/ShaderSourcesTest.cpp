// What hot reload needs before any compiler runs: the files a shader is made of, noticing
// when they change, and the compiler command lines.
#include "core/FileWatcher.h"
#include "gpu/ExternalShaderCompiler.h"
#include "gpu/ShaderIncludes.h"

#include <gtest/gtest.h>

#include <fstream>

namespace firmament {
namespace {

std::filesystem::path freshFolder(const char* name) {
    const auto folder = std::filesystem::temp_directory_path() / name;
    std::filesystem::remove_all(folder);
    std::filesystem::create_directories(folder / "common");
    std::filesystem::create_directories(folder / "sky");
    return folder;
}

TEST(ShaderSources, IncludesAreFollowedFromTheRoot) {
    const auto root = freshFolder("firmament-includes-test");
    std::ofstream(root / "sky" / "sky.hlsl") << "#include \"common/a.hlsli\"\n  #  include \"common/b.hlsli\"\nfloat4 main() : SV_Target { return 0; }\n";
    std::ofstream(root / "common" / "a.hlsli") << "#include \"common/b.hlsli\"\n#include \"common/missing.hlsli\"\n";
    std::ofstream(root / "common" / "b.hlsli") << "#include \"common/a.hlsli\"\n// #include in a comment after code is not at the line start: \" \n";
    const auto files = shaderSourceFiles(root, "sky/sky.hlsl");
    EXPECT_EQ(files, (std::vector<std::string>{"sky/sky.hlsl", "common/a.hlsli", "common/b.hlsli", "common/missing.hlsli"}));
}

TEST(ShaderSources, WatcherReportsChangedCreatedAndDeletedFiles) {
    const auto root = freshFolder("firmament-watcher-test");
    std::ofstream(root / "a.hlsl") << "one";
    FileWatcher watcher;
    watcher.watch(root / "a.hlsl");
    watcher.watch(root / "b.hlsl");  // not there yet
    EXPECT_TRUE(watcher.poll().empty());
    std::ofstream(root / "a.hlsl") << "two, longer";
    EXPECT_EQ(watcher.poll(), std::vector<std::filesystem::path>{root / "a.hlsl"});
    EXPECT_TRUE(watcher.poll().empty());  // reported once
    std::ofstream(root / "b.hlsl") << "new";
    EXPECT_EQ(watcher.poll(), std::vector<std::filesystem::path>{root / "b.hlsl"});
    std::filesystem::remove(root / "a.hlsl");
    EXPECT_EQ(watcher.poll(), std::vector<std::filesystem::path>{root / "a.hlsl"});
}

TEST(ShaderSources, CompilerCommandLines) {
    const ShaderKey key{"sky/sky.hlsl", "ps_main", "ps_5_0", {"SAMPLES=16", "USE_LUT=1"}};
    EXPECT_EQ(vkd3dWrapperSource(key),
              "// Firmament hot reload: sky/sky.hlsl|ps_main|ps_5_0|SAMPLES=16,USE_LUT=1\n"
              "#define SAMPLES 16\n#define USE_LUT 1\n#include \"sky/sky.hlsl\"\n");
    EXPECT_EQ(vkd3dShellCommand("/usr/bin/vkd3d-compiler", "/src/my shaders", key, "/tmp/w.hlsl", "/tmp/o's.cso"),
              "cd '/src/my shaders' && '/usr/bin/vkd3d-compiler' -x hlsl -b dxbc-tpf -p 'ps_5_0' -e 'ps_main' "
              "-o '/tmp/o'\\''s.cso' '/tmp/w.hlsl'");
    // Through the build's cache of compiled shaders (cmake/shader-cache.sh), which takes the
    // compiler and its arguments.
    EXPECT_EQ(vkd3dShellCommand("/usr/bin/vkd3d-compiler", "/src", key, "/tmp/w.hlsl", "/tmp/o.cso", "/src/cmake/shader-cache.sh"),
              "cd '/src' && sh '/src/cmake/shader-cache.sh' '/usr/bin/vkd3d-compiler' -x hlsl -b dxbc-tpf -p 'ps_5_0' -e 'ps_main' "
              "-o '/tmp/o.cso' '/tmp/w.hlsl'");
    // Every job once, as many at a time as the host has cores.
    EXPECT_EQ(parallelJobsCommand({"/tmp/a.sh", "/tmp/b c.sh"}),
              "printf '%s\\n' '/tmp/a.sh' '/tmp/b c.sh' | xargs -P \"$(nproc 2>/dev/null || echo 2)\" -n 1 sh");
    EXPECT_EQ(fxcCommandLine(L"C:\\Kits\\fxc.exe", L"C:\\my shaders", key, L"C:\\t\\o.cso"),
              L"C:\\Kits\\fxc.exe /nologo /O3 /T ps_5_0 /E ps_main /I \"C:\\my shaders\" /D SAMPLES=16 /D USE_LUT=1 "
              L"/Fo C:\\t\\o.cso \"C:\\my shaders\\sky/sky.hlsl\"");
}

}  // namespace
}  // namespace firmament
