// Everything made on the Direct3D device (DeviceResources.h): the device, the shader library
// with the hot-reload compiler chosen for it, the swap chain, the renderer and the GUI; and what
// they are made from (the shader folder, the tables' cache).
#include "app/DeviceResources.h"

#include "core/Error.h"
#include "core/Log.h"
#include "gpu/PrecompiledShaders.h"
#include "gpu/SourceShaderCompilers.h"

#include <system_error>
#include <utility>

namespace firmament {

namespace {

std::filesystem::path executableFolder() {
    wchar_t path[MAX_PATH];
    const DWORD length = GetModuleFileNameW(nullptr, path, MAX_PATH);
    return std::filesystem::path(std::wstring(path, length)).parent_path();
}

DeviceOptions deviceOptions(const Options& options) {
    DeviceOptions d;
    d.driver = options.driver;
    d.adapterIndex = options.adapter;
    return d;
}

}  // namespace

std::unique_ptr<ShaderCompiler> openShaderFolder(const Options& options) {
    const auto folder = options.shaderDir.value_or(executableFolder() / "shaders");
    auto shaders = std::make_unique<PrecompiledShaders>(folder);
    log::info("shaders: " + std::to_string(shaders->size()) + " precompiled permutations in " + folder.string());
    return shaders;
}

TableStorage tableStorage(const Options& options) {
    TableStorage storage;
    storage.exportFolder = options.exportLuts;
    storage.mediaFolder = executableFolder() / "media";
    if (options.noCache) return storage;
    if (options.cacheDir) {
        storage.cacheFolder = options.cacheDir;
    } else if (const wchar_t* localAppData = _wgetenv(L"LOCALAPPDATA"); localAppData && *localAppData) {
        storage.cacheFolder = std::filesystem::path(localAppData) / "Firmament" / "cache";
    } else {
        storage.cacheFolder = executableFolder() / "cache";
    }
    return storage;
}

DeviceResources::DeviceResources(const Options& options, std::unique_ptr<ShaderCompiler> precompiled, const TableStorage& storage,
                                 HWND window, int width, int height)
    : hdrPrecision(options.hdrFloat32 ? HdrPrecision::Float32 : HdrPrecision::Half),
      device(deviceOptions(options)),
      shaders(device.device(), std::move(precompiled)),
      renderer(device.device(), device.context(), shaders, storage) {
    log::info("device: " + device.describe());

    // Hot reload compiles from the HLSL folder the build used, unless told otherwise.
    const auto& compiled = static_cast<const PrecompiledShaders&>(shaders.compiler());
    const auto sourceRoot = options.shaderSource ? options.shaderSource : compiled.sourceRoot();
    const auto choice = parseSourceCompilerChoice(options.shaderCompiler).value_or(SourceCompilerChoice::Auto);
    std::error_code ec;
    if (choice == SourceCompilerChoice::None) {
        log::info("shader hot reload: off (--shader-compiler none)");
    } else if (!sourceRoot || !std::filesystem::is_directory(*sourceRoot, ec)) {
        if (options.shaderSource) throw Error("--shader-source: '" + options.shaderSource->string() + "' is not a folder");
        log::warning("shader hot reload: off (the HLSL folder " + (sourceRoot ? sourceRoot->string() : std::string("?")) +
                     " is not there; pass --shader-source)");
    } else if (auto compiler = makeSourceCompiler(choice, *sourceRoot, compiled.cacheLauncher())) {
        log::info("shader hot reload: " + compiler->name() + " from " + sourceRoot->string());
        shaders.enableHotReload(std::move(compiler), *sourceRoot);
    } else {
        log::warning("shader hot reload: off (no shader compiler found: d3dcompiler_47.dll or fxc.exe)");
    }

    if (!options.headless) swapChain = std::make_unique<SwapChain>(device, window, width, height);
    overlay = std::make_unique<Overlay>(window, device.device(), device.context());
    renderer.resize(width, height, !swapChain, hdrPrecision);
    if (hdrPrecision == HdrPrecision::Float32) log::info("HDR frame: 32-bit floats (--hdr-float32)");
}

}  // namespace firmament
