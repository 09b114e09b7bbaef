#include "gpu/D3D11Implementation.h"

#include <windows.h>
#include <wrl/client.h>

namespace firmament {

namespace {
// IDXGIVkInteropFactory, DXVK's DXGI factory interface for Vulkan interop.
constexpr GUID kDxvkInteropFactory = {0x4c5e1b0d, 0xb0c8, 0x4131, {0xbf, 0xd8, 0x9b, 0x24, 0x76, 0xf7, 0xf4, 0x08}};

bool underWine() {
    const HMODULE ntdll = GetModuleHandleW(L"ntdll.dll");
    return ntdll != nullptr && GetProcAddress(ntdll, "wine_get_version") != nullptr;
}
}  // namespace

D3D11Implementation detectD3D11Implementation(IDXGIFactory1* factory) {
    Microsoft::WRL::ComPtr<IUnknown> interop;
    if (factory != nullptr && SUCCEEDED(factory->QueryInterface(kDxvkInteropFactory, reinterpret_cast<void**>(interop.GetAddressOf()))))
        return D3D11Implementation::Dxvk;
    return underWine() ? D3D11Implementation::Wined3d : D3D11Implementation::Windows;
}

std::string implementationName(D3D11Implementation implementation) {
    switch (implementation) {
        case D3D11Implementation::Dxvk: return "DXVK";
        case D3D11Implementation::Wined3d: return "wined3d (Wine)";
        case D3D11Implementation::Windows: break;
    }
    return "Direct3D 11 (Windows)";
}

std::string implementationId(D3D11Implementation implementation) {
    switch (implementation) {
        case D3D11Implementation::Dxvk: return "dxvk";
        case D3D11Implementation::Wined3d: return "wined3d";
        case D3D11Implementation::Windows: break;
    }
    return "windows";
}

}  // namespace firmament
