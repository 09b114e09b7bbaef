#pragma once
// A flip-model swap chain for a window: two 8-bit UNORM buffers (shaders encode sRGB
// themselves), resize on WM_SIZE, presentation with or without VSync (tearing allowed
// where supported, for honest frame times with VSync off).
#include "gpu/Device.h"

#include <windows.h>

namespace firmament {

class SwapChain {
public:
    SwapChain(const Device& device, HWND window, int width, int height);

    void resize(int width, int height);  // no-op for a zero size (minimized)
    // Empty when presented (or occluded); the loss's name after DXGI_ERROR_DEVICE_REMOVED or
    // _RESET, which the caller answers by making the device and everything on it again.
    std::string present(bool vsync);

    ID3D11Texture2D* backBuffer() const { return backBuffer_.Get(); }
    ID3D11RenderTargetView* backBufferRtv() const { return rtv_.Get(); }
    int width() const { return width_; }
    int height() const { return height_; }

    static constexpr DXGI_FORMAT kFormat = DXGI_FORMAT_R8G8B8A8_UNORM;

private:
    void createViews();

    ID3D11Device* device_;
    ComPtr<IDXGISwapChain1> swapChain_;
    ComPtr<ID3D11Texture2D> backBuffer_;
    ComPtr<ID3D11RenderTargetView> rtv_;
    int width_;
    int height_;
    bool tearing_;
};

}  // namespace firmament
