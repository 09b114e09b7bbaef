#include "gpu/SwapChain.h"

#include "gpu/Hresult.h"

#include <vector>

namespace firmament {

namespace {
// The factories whose window association decides what Alt+Enter does: the one that makes the swap
// chain (Windows reads its association, and resets it when the swap chain is made, so it is set
// after that), and the one the device was made from (D3D11CreateDevice makes its own when given no
// adapter; Wine's DXGI reads that one's association, the first made, so it is set before too).
std::vector<ComPtr<IDXGIFactory>> associatedFactories(const Device& device) {
    std::vector<ComPtr<IDXGIFactory>> factories{device.factory()};
    ComPtr<IDXGIDevice> dxgiDevice;
    ComPtr<IDXGIAdapter> adapter;
    ComPtr<IDXGIFactory> deviceFactory;
    if (SUCCEEDED(device.driverDevice()->QueryInterface(IID_PPV_ARGS(&dxgiDevice))) && SUCCEEDED(dxgiDevice->GetAdapter(&adapter)) &&
        SUCCEEDED(adapter->GetParent(IID_PPV_ARGS(&deviceFactory))) && deviceFactory.Get() != factories.front().Get())
        factories.push_back(deviceFactory);
    return factories;
}
}  // namespace

SwapChain::SwapChain(const Device& device, HWND window, int width, int height)
    : device_(device.device()), width_(width), height_(height), tearing_(device.tearingSupported()) {
    DXGI_SWAP_CHAIN_DESC1 desc{};
    desc.Width = static_cast<UINT>(width);
    desc.Height = static_cast<UINT>(height);
    desc.Format = kFormat;
    desc.SampleDesc.Count = 1;
    desc.BufferUsage = DXGI_USAGE_RENDER_TARGET_OUTPUT;
    desc.BufferCount = 2;
    desc.Scaling = DXGI_SCALING_STRETCH;
    desc.SwapEffect = DXGI_SWAP_EFFECT_FLIP_DISCARD;
    desc.AlphaMode = DXGI_ALPHA_MODE_IGNORE;
    desc.Flags = tearing_ ? DXGI_SWAP_CHAIN_FLAG_ALLOW_TEARING : 0;
    // Alt+Enter is the window's own borderless full screen (Window::toggleFullScreen), so DXGI must
    // not toggle its own too: each would undo the other.
    const std::vector<ComPtr<IDXGIFactory>> factories = associatedFactories(device);
    for (const auto& factory : factories) factory->MakeWindowAssociation(window, DXGI_MWA_NO_ALT_ENTER);
    check(device.factory()->CreateSwapChainForHwnd(device.driverDevice(), window, &desc, nullptr, nullptr, &swapChain_),
          "CreateSwapChainForHwnd");
    for (const auto& factory : factories) factory->MakeWindowAssociation(window, DXGI_MWA_NO_ALT_ENTER);
    createViews();
}

void SwapChain::createViews() {
    check(swapChain_->GetBuffer(0, IID_PPV_ARGS(&backBuffer_)), "IDXGISwapChain::GetBuffer");
    check(device_->CreateRenderTargetView(backBuffer_.Get(), nullptr, &rtv_), "CreateRenderTargetView (back buffer)");
}

void SwapChain::resize(int width, int height) {
    if (width <= 0 || height <= 0 || (width == width_ && height == height_)) return;
    rtv_.Reset();
    backBuffer_.Reset();
    ComPtr<ID3D11DeviceContext> context;
    device_->GetImmediateContext(&context);
    context->OMSetRenderTargets(0, nullptr, nullptr);
    context->Flush();
    check(swapChain_->ResizeBuffers(0, static_cast<UINT>(width), static_cast<UINT>(height), DXGI_FORMAT_UNKNOWN,
                                    tearing_ ? DXGI_SWAP_CHAIN_FLAG_ALLOW_TEARING : 0),
          "IDXGISwapChain::ResizeBuffers");
    width_ = width;
    height_ = height;
    createViews();
}

std::string SwapChain::present(bool vsync) {
    const UINT flags = (!vsync && tearing_) ? DXGI_PRESENT_ALLOW_TEARING : 0;
    const HRESULT hr = swapChain_->Present(vsync ? 1 : 0, flags);
    if (hr == DXGI_STATUS_OCCLUDED) return {};
    if (hr == DXGI_ERROR_DEVICE_REMOVED || hr == DXGI_ERROR_DEVICE_RESET) return deviceLossName(hr);
    check(hr, "IDXGISwapChain::Present");
    return {};
}

}  // namespace firmament
