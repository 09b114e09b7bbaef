#include "gpu/SourceShaderCompilers.h"

#include "core/ChildProcess.h"
#include "core/Error.h"
#include "gpu/D3DCompileShaders.h"
#include "gpu/ExternalShaderCompiler.h"

#include <windows.h>

namespace firmament {

namespace {

constexpr const char* kHostVkd3d = "/usr/bin/vkd3d-compiler";

bool hostVkd3dPresent() {
    if (!runningUnderWine()) return false;
    std::error_code ec;
    return std::filesystem::exists(std::filesystem::path(L"Z:\\usr\\bin\\vkd3d-compiler"), ec);
}

// The build's cache launcher, if the host has it at that path (a program copied elsewhere may not).
std::string presentLauncher(const std::string& launcher) {
    std::error_code ec;
    if (launcher.empty() || !runningUnderWine() || !std::filesystem::is_regular_file(std::filesystem::path("Z:" + launcher), ec)) return {};
    return launcher;
}

std::optional<std::filesystem::path> fxcOnPath() {
    wchar_t found[MAX_PATH];
    const DWORD length = SearchPathW(nullptr, L"fxc.exe", nullptr, MAX_PATH, found, nullptr);
    if (length == 0 || length >= MAX_PATH) return std::nullopt;
    return std::filesystem::path(std::wstring(found, length));
}

}  // namespace

std::optional<SourceCompilerChoice> parseSourceCompilerChoice(std::string_view name) {
    if (name == "auto") return SourceCompilerChoice::Auto;
    if (name == "d3dcompile") return SourceCompilerChoice::D3DCompile;
    if (name == "vkd3d") return SourceCompilerChoice::Vkd3d;
    if (name == "fxc") return SourceCompilerChoice::Fxc;
    if (name == "none") return SourceCompilerChoice::None;
    return std::nullopt;
}

std::unique_ptr<ShaderCompiler> makeSourceCompiler(SourceCompilerChoice choice, const std::filesystem::path& root,
                                                   const std::string& cacheLauncher) {
    switch (choice) {
        case SourceCompilerChoice::None:
            return nullptr;
        case SourceCompilerChoice::D3DCompile:
            return std::make_unique<D3DCompileShaders>(root);
        case SourceCompilerChoice::Vkd3d:
            if (!hostVkd3dPresent()) throw Error(std::string("--shader-compiler vkd3d needs Wine and ") + kHostVkd3d + " on the host");
            return std::make_unique<ExternalShaderCompiler>(ExternalCompilerKind::Vkd3dOnHost, kHostVkd3d, root, presentLauncher(cacheLauncher));
        case SourceCompilerChoice::Fxc: {
            const auto fxc = fxcOnPath();
            if (!fxc) throw Error("--shader-compiler fxc: fxc.exe is not on PATH (it ships with the Windows SDK)");
            return std::make_unique<ExternalShaderCompiler>(ExternalCompilerKind::Fxc, *fxc, root);
        }
        case SourceCompilerChoice::Auto:
            // Under Wine its own d3dcompiler_47 lacks features our shaders use: prefer the
            // build's compiler on the host.
            if (hostVkd3dPresent()) return std::make_unique<ExternalShaderCompiler>(ExternalCompilerKind::Vkd3dOnHost, kHostVkd3d, root, presentLauncher(cacheLauncher));
            if (D3DCompileShaders::available()) return std::make_unique<D3DCompileShaders>(root);
            if (const auto fxc = fxcOnPath()) return std::make_unique<ExternalShaderCompiler>(ExternalCompilerKind::Fxc, *fxc, root);
            return nullptr;
    }
    return nullptr;
}

}  // namespace firmament
