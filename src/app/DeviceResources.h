#pragma once
// What the program makes on the Direct3D device, as one object that a lost device replaces
// whole (docs/reliability.md, "A lost device"), and what it is made from: the compiled shaders'
// folder (checked before any window exists) and the tables' cache.
#include "app/CommandLine.h"
#include "gpu/Device.h"
#include "gpu/ShaderLibrary.h"
#include "gpu/SwapChain.h"
#include "render/Renderer.h"
#include "tables/CachedTables.h"
#include "ui/Overlay.h"

#include <memory>

#include <windows.h>

namespace firmament {

// The compiled shaders of --shader-dir (else 'shaders' beside the program); throws Error naming
// a folder that is not there or holds no manifest.
std::unique_ptr<ShaderCompiler> openShaderFolder(const Options& options);

// The cache of the pre-computed tables: --cache-dir, else %LOCALAPPDATA%\Firmament\cache,
// else a "cache" folder beside the program; --export-luts' folder; the media beside the program.
TableStorage tableStorage(const Options& options);

// Everything made on the Direct3D device, made in this order and destroyed in the reverse: the
// device, the shader library, the swap chain (none when headless), the renderer with every
// technique and its tables (loaded from the cache where they are there) and the GUI. After a
// device loss (DXGI_ERROR_DEVICE_REMOVED or _RESET) the App destroys it and makes it again,
// whole; what lives outside it (the settings and camera, the window, input, the flight and the
// clock) is kept.
struct DeviceResources {
    DeviceResources(const Options& options, std::unique_ptr<ShaderCompiler> precompiled, const TableStorage& storage, HWND window,
                    int width, int height);  // throws Error

    HdrPrecision hdrPrecision;  // the frame's HDR floats (--hdr-float32)
    Device device;
    ShaderLibrary shaders;
    std::unique_ptr<SwapChain> swapChain;  // null when headless
    Renderer renderer;
    std::unique_ptr<Overlay> overlay;
};

}  // namespace firmament
