// Hot reload end to end on the WARP device: the test shaders' "reload" technique is copied
// to a temporary folder and compiled from there by the backend the program would pick
// (vkd3d-compiler under Wine, D3DCompile on Windows). Edits change what is drawn; a broken
// edit keeps the previous shaders and reports the compiler's message; fixing it recovers;
// a technique's shaders are replaced all together or not at all.
#include "WarpDevice.h"
#include "gpu/D3DCompileShaders.h"
#include "gpu/SourceShaderCompilers.h"
#include "gpu/Texture.h"

#include <fstream>

namespace firmament::test {
namespace {

const ShaderKey kVertex{"reload/solid_color.hlsl", "vs_main", "vs_5_0", {}};
const ShaderKey kSolid{"reload/solid_color.hlsl", "ps_main", "ps_5_0", {}};
const ShaderKey kTint{"reload/tint.hlsl", "ps_main", "ps_5_0", {}};

using Rgba = std::array<std::uint8_t, 4>;

class HotReload : public WarpDevice {
protected:
    void SetUp() override {
        WarpDevice::SetUp();
        const auto sourceRoot = PrecompiledShaders(testShaders()).sourceRoot();
        ASSERT_TRUE(sourceRoot.has_value()) << "the test manifest names no #source folder";
        // One folder per test: CTest runs tests in parallel processes, and a shared folder
        // would be wiped and re-copied under a test that is still running.
        root = std::filesystem::temp_directory_path() /
               ("firmament-hot-reload-" + std::string(::testing::UnitTest::GetInstance()->current_test_info()->name()));
        std::filesystem::remove_all(root);
        std::filesystem::create_directories(root / "reload");
        std::filesystem::copy(*sourceRoot / "reload", root / "reload", std::filesystem::copy_options::recursive);
        output = createColorTexture(device(), 4, 4, DXGI_FORMAT_R8G8B8A8_UNORM, D3D11_BIND_RENDER_TARGET);
    }

    void write(const std::string& file, const std::string& text) { std::ofstream(root / file, std::ios::binary) << text; }
    void setColor(const std::string& hlslColor) { write("reload/color.hlsli", "#define RELOAD_COLOR " + hlslColor + "\n"); }

    // Draws a full-screen triangle with `pixel` from `library` and reads one texel.
    Rgba draw(ShaderLibrary& library, const ShaderKey& pixel) {
        const D3D11_VIEWPORT viewport{0.0f, 0.0f, 4.0f, 4.0f, 0.0f, 1.0f};
        ID3D11RenderTargetView* target = output.rtv.Get();
        context()->OMSetRenderTargets(1, &target, nullptr);
        context()->RSSetViewports(1, &viewport);
        context()->IASetInputLayout(nullptr);
        context()->IASetPrimitiveTopology(D3D11_PRIMITIVE_TOPOLOGY_TRIANGLELIST);
        context()->VSSetShader(library.vertexShader(kVertex), nullptr, 0);
        context()->PSSetShader(library.pixelShader(pixel), nullptr, 0);
        context()->Draw(3, 0);
        const ReadbackImage image = readTexture2D(device(), context(), output.texture.Get());
        return {image.bytes[0], image.bytes[1], image.bytes[2], image.bytes[3]};
    }

    std::unique_ptr<ShaderLibrary> reloadingLibrary() {
        auto library = std::make_unique<ShaderLibrary>(device(), std::make_unique<PrecompiledShaders>(testShaders()));
        auto compiler = makeSourceCompiler(SourceCompilerChoice::Auto, root);
        if (!compiler) return nullptr;
        std::printf("hot reload backend: %s\n", compiler->name().c_str());
        library->enableHotReload(std::move(compiler), root);
        return library;
    }

    std::filesystem::path root;
    Texture2D output;
};

TEST_F(HotReload, EditsChangeTheOutputAndBrokenEditsKeepThePreviousShader) {
    auto library = reloadingLibrary();
    if (!library) GTEST_SKIP() << "no shader compiler on this machine";
    EXPECT_EQ(draw(*library, kSolid), (Rgba{64, 128, 191, 255}));  // precompiled: float3(0.25, 0.5, 0.75)
    EXPECT_FALSE(library->reloadChanged().attempted());             // nothing changed yet

    setColor("float3(1.0, 0.0, 0.5)");  // an edit of an included file
    ReloadResult result = library->reloadChanged();
    EXPECT_EQ(result.techniquesReloaded, 1);
    EXPECT_EQ(result.shadersCompiled, 2);  // both permutations of the technique that are loaded
    EXPECT_TRUE(library->errors().empty());
    EXPECT_EQ(draw(*library, kSolid), (Rgba{255, 0, 128, 255}));

    setColor("float3(1.0, 0.0, ");  // a syntax error
    result = library->reloadChanged();
    EXPECT_EQ(result.failedTechniques, std::vector<std::string>{"reload"});
    ASSERT_EQ(library->errors().count("reload"), 1u);
    const std::string message = library->errors().at("reload");
    EXPECT_NE(message.find("reload/solid_color.hlsl|ps_main|ps_5_0|"), std::string::npos) << message;
    EXPECT_GT(message.size(), 60u) << "the compiler's own message is missing: " << message;
    std::printf("reported compiler message:\n%s\n", message.c_str());
    EXPECT_EQ(draw(*library, kSolid), (Rgba{255, 0, 128, 255}));  // the previous shader still runs

    setColor("float3(0.0, 1.0, 0.0)");  // fixed
    result = library->reloadChanged();
    EXPECT_EQ(result.techniquesReloaded, 1);
    EXPECT_TRUE(library->errors().empty());
    EXPECT_EQ(draw(*library, kSolid), (Rgba{0, 255, 0, 255}));
}

TEST_F(HotReload, ATechniqueIsReplacedAllTogetherOrNotAtAll) {
    auto library = reloadingLibrary();
    if (!library) GTEST_SKIP() << "no shader compiler on this machine";
    EXPECT_EQ(draw(*library, kTint), (Rgba{0, 0, 255, 255}));
    EXPECT_EQ(draw(*library, kSolid), (Rgba{64, 128, 191, 255}));

    // A good edit of one shader and a broken edit of the other, in the same technique.
    setColor("float3(1.0, 1.0, 1.0)");
    write("reload/tint.hlsl", "float4 ps_main() : SV_Target { return undeclared_value; }\n");
    const ReloadResult result = library->reloadAll();  // F8
    EXPECT_EQ(result.failedTechniques, std::vector<std::string>{"reload"});
    EXPECT_NE(library->errors().at("reload").find("reload/tint.hlsl"), std::string::npos);
    EXPECT_EQ(draw(*library, kSolid), (Rgba{64, 128, 191, 255})) << "the good edit must wait for the whole technique";
    EXPECT_EQ(draw(*library, kTint), (Rgba{0, 0, 255, 255}));

    write("reload/tint.hlsl", "float4 ps_main() : SV_Target { return float4(1.0, 0.0, 0.0, 1.0); }\n");
    EXPECT_EQ(library->reloadAll().techniquesReloaded, 1);
    EXPECT_EQ(draw(*library, kSolid), (Rgba{255, 255, 255, 255}));
    EXPECT_EQ(draw(*library, kTint), (Rgba{255, 0, 0, 255}));
}

// The permutations drawn in the last frames are compiled first and swapped in before the reload
// returns; the technique's others follow in the background. One asked for before the background
// compile lands is compiled from the edited source then; one that fails in the background falls
// back to the precompiled version and reports its message.
TEST_F(HotReload, ThePermutationsInUseComeFirstAndTheRestFollowInTheBackground) {
    auto library = reloadingLibrary();
    if (!library) GTEST_SKIP() << "no shader compiler on this machine";
    const auto drawOnlySolid = [&] {  // two frames that draw the solid colour and not the tint
        for (int frame = 0; frame < 2; ++frame) {
            library->beginFrame();
            draw(*library, kSolid);
        }
    };
    EXPECT_EQ(draw(*library, kTint), (Rgba{0, 0, 255, 255}));
    drawOnlySolid();

    setColor("float3(0.0, 1.0, 0.0)");
    write("reload/tint.hlsl", "float4 ps_main() : SV_Target { return float4(1.0, 0.0, 0.0, 1.0); }\n");
    ReloadResult result = library->reloadAll();
    EXPECT_EQ(result.techniquesReloaded, 1);
    EXPECT_EQ(result.shadersCompiled, 2) << "the vertex and solid-colour shaders, in use";
    EXPECT_EQ(result.shadersInBackground, 1) << "the tint, not drawn in the last two frames";
    EXPECT_EQ(draw(*library, kSolid), (Rgba{0, 255, 0, 255}));
    library->waitForBackgroundCompile();
    EXPECT_FALSE(library->backgroundCompilePending());
    EXPECT_EQ(draw(*library, kTint), (Rgba{255, 0, 0, 255}));
    EXPECT_TRUE(library->errors().empty());

    // Asked for before the background compile lands: compiled then, from the edited source.
    drawOnlySolid();
    write("reload/tint.hlsl", "float4 ps_main() : SV_Target { return float4(1.0, 1.0, 1.0, 1.0); }\n");
    EXPECT_EQ(library->reloadAll().shadersInBackground, 1);
    EXPECT_EQ(draw(*library, kTint), (Rgba{255, 255, 255, 255}));
    library->waitForBackgroundCompile();
    EXPECT_EQ(draw(*library, kTint), (Rgba{255, 255, 255, 255}));

    // Broken where it is not in use: the reload succeeds for what is drawn, the background
    // compile reports the tint's error, and the tint falls back to the precompiled shader.
    drawOnlySolid();
    write("reload/tint.hlsl", "float4 ps_main() : SV_Target { return undeclared_value; }\n");
    result = library->reloadAll();
    EXPECT_TRUE(result.failedTechniques.empty());
    library->waitForBackgroundCompile();
    ASSERT_EQ(library->errors().count("reload"), 1u);
    EXPECT_NE(library->errors().at("reload").find("reload/tint.hlsl"), std::string::npos) << library->errors().at("reload");
    EXPECT_EQ(draw(*library, kTint), (Rgba{0, 0, 255, 255}));
    EXPECT_EQ(draw(*library, kSolid), (Rgba{0, 255, 0, 255}));
}

// D3DCompile, the default backend on Windows. Wine's own d3dcompiler_47 compiles a shader
// this simple; on Windows it is Microsoft's.
TEST_F(HotReload, D3DCompileBackendCompilesFromTheSourceFolder) {
    if (!D3DCompileShaders::available()) GTEST_SKIP() << "d3dcompiler_47.dll is not on this machine";
    D3DCompileShaders compiler(root);
    setColor("float3(0.0, 0.0, 1.0)");
    auto library = std::make_unique<ShaderLibrary>(device(), std::make_unique<PrecompiledShaders>(testShaders()));
    library->enableHotReload(std::make_unique<D3DCompileShaders>(root), root);
    EXPECT_EQ(draw(*library, kSolid), (Rgba{64, 128, 191, 255}));
    EXPECT_EQ(library->reloadAll().techniquesReloaded, 1) << (library->errors().empty() ? "" : library->errors().begin()->second);
    EXPECT_EQ(draw(*library, kSolid), (Rgba{0, 0, 255, 255}));

    const CompileResult broken = compiler.compile({"reload/missing.hlsl", "ps_main", "ps_5_0", {}});
    EXPECT_FALSE(broken.ok);
    EXPECT_NE(broken.log.find("missing.hlsl"), std::string::npos) << broken.log;
}

}  // namespace
}  // namespace firmament::test
