#pragma once
// Which Direct3D 11 implementation runs the program: Windows' own, Wine's wined3d (Direct3D 11
// over OpenGL) or DXVK (over Vulkan, under Wine or on Windows). Pictures and timings depend on
// it, so the log, the captures' header and the benchmark JSON name it beside the adapter.
#include <dxgi.h>

#include <string>

namespace firmament {

enum class D3D11Implementation { Windows, Wined3d, Dxvk };

// DXVK's DXGI factory answers for its Vulkan interop interface, which no other implementation
// has; Wine is known by ntdll's wine_get_version.
D3D11Implementation detectD3D11Implementation(IDXGIFactory1* factory);
// "Direct3D 11 (Windows)", "wined3d (Wine)", "DXVK".
std::string implementationName(D3D11Implementation implementation);
// The short name the tools and the tests use: "windows", "wined3d", "dxvk".
std::string implementationId(D3D11Implementation implementation);

}  // namespace firmament
