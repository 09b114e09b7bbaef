#include "gpu/Device.h"

#include "core/Error.h"
#include "gpu/CountingDevice.h"
#include "gpu/Hresult.h"

#include <cstdio>
#include <vector>

namespace firmament {

std::string featureLevelName(D3D_FEATURE_LEVEL level) {
    switch (level) {
        case D3D_FEATURE_LEVEL_11_0: return "11_0";
        case D3D_FEATURE_LEVEL_11_1: return "11_1";
        case D3D_FEATURE_LEVEL_12_0: return "12_0";
        case D3D_FEATURE_LEVEL_12_1: return "12_1";
        default: return "below 11_0";
    }
}

Device::Device(const DeviceOptions& options) {
    check(CreateDXGIFactory1(IID_PPV_ARGS(&factory_)), "CreateDXGIFactory1");

    implementation_ = detectD3D11Implementation(factory_.Get());

    ComPtr<IDXGIAdapter1> adapter;
    D3D_DRIVER_TYPE driverType = options.driver == DriverType::Warp ? D3D_DRIVER_TYPE_WARP : D3D_DRIVER_TYPE_HARDWARE;
    // DXVK has no WARP: asked for one, it warns of an unsupported driver type and takes its first
    // Vulkan device anyway. Asking for that device is the same without the warning; the tools run
    // DXVK on lavapipe, a CPU device, as WARP is one.
    if (implementation_ == D3D11Implementation::Dxvk && driverType == D3D_DRIVER_TYPE_WARP) {
        driverType = D3D_DRIVER_TYPE_HARDWARE;
        warpNotAvailable_ = true;
    }
    if (options.adapterIndex) {
        if (factory_->EnumAdapters1(*options.adapterIndex, &adapter) == DXGI_ERROR_NOT_FOUND) {
            std::string list;
            ComPtr<IDXGIAdapter1> each;
            for (UINT i = 0; factory_->EnumAdapters1(i, &each) != DXGI_ERROR_NOT_FOUND; ++i) {
                DXGI_ADAPTER_DESC1 desc{};
                each->GetDesc1(&desc);
                list += "\n  " + std::to_string(i) + ": " + narrow(desc.Description);
            }
            throw Error("--adapter " + std::to_string(*options.adapterIndex) +
                        ": no such adapter; the adapters are:" + (list.empty() ? " none" : list));
        }
        driverType = D3D_DRIVER_TYPE_UNKNOWN;  // required when an adapter is given
    }

    UINT flags = D3D11_CREATE_DEVICE_BGRA_SUPPORT;
    if (options.debugLayer) flags |= D3D11_CREATE_DEVICE_DEBUG;
    const D3D_FEATURE_LEVEL levels[] = {D3D_FEATURE_LEVEL_11_1, D3D_FEATURE_LEVEL_11_0};
    HRESULT hr = D3D11CreateDevice(adapter.Get(), driverType, nullptr, flags, levels, 2, D3D11_SDK_VERSION,
                                   &driver_, &featureLevel_, &context_);
    if (hr == E_INVALIDARG)  // runtimes that do not know 11_1
        hr = D3D11CreateDevice(adapter.Get(), driverType, nullptr, flags, levels + 1, 1, D3D11_SDK_VERSION,
                               &driver_, &featureLevel_, &context_);
    check(hr, options.driver == DriverType::Warp ? "D3D11CreateDevice (WARP)" : "D3D11CreateDevice");

    device_.Attach(new CountingDevice(driver_.Get(), liveObjects_));

    ComPtr<IDXGIDevice> dxgiDevice;
    ComPtr<IDXGIAdapter> deviceAdapter;
    if (SUCCEEDED(driver_.As(&dxgiDevice)) && SUCCEEDED(dxgiDevice->GetAdapter(&deviceAdapter))) {
        DXGI_ADAPTER_DESC desc{};
        deviceAdapter->GetDesc(&desc);
        adapterName_ = narrow(desc.Description);
    }

    ComPtr<IDXGIFactory5> factory5;
    if (SUCCEEDED(factory_.As(&factory5))) {
        BOOL allowTearing = FALSE;
        if (SUCCEEDED(factory5->CheckFeatureSupport(DXGI_FEATURE_PRESENT_ALLOW_TEARING, &allowTearing,
                                                    sizeof allowTearing)))
            tearingSupported_ = allowTearing == TRUE;
    }
}

std::string deviceLossName(HRESULT hr) {
    switch (hr) {
        case DXGI_ERROR_DEVICE_REMOVED: return "DXGI_ERROR_DEVICE_REMOVED";
        case DXGI_ERROR_DEVICE_RESET: return "DXGI_ERROR_DEVICE_RESET";
        case DXGI_ERROR_DEVICE_HUNG: return "DXGI_ERROR_DEVICE_HUNG";
        case DXGI_ERROR_DRIVER_INTERNAL_ERROR: return "DXGI_ERROR_DRIVER_INTERNAL_ERROR";
        case DXGI_ERROR_INVALID_CALL: return "DXGI_ERROR_INVALID_CALL";
        default: {
            char code[16];
            std::snprintf(code, sizeof code, "0x%08lX", static_cast<unsigned long>(hr));
            return code;
        }
    }
}

std::string Device::removedReason() const {
    const HRESULT hr = device_->GetDeviceRemovedReason();
    return hr == S_OK ? std::string() : deviceLossName(hr);
}

LiveObjectCounts Device::liveObjects() const {
    waitForGpu();  // Wine destroys objects on its command-stream thread
    return liveObjects_.counts();
}

void Device::waitForGpu() const {
    // An event query made on the driver's device, so that it is not counted itself.
    D3D11_QUERY_DESC desc{D3D11_QUERY_EVENT, 0};
    ComPtr<ID3D11Query> finished;
    check(driver_->CreateQuery(&desc, &finished), "CreateQuery (event)");
    context_->End(finished.Get());
    context_->Flush();
    BOOL signalled = FALSE;
    // S_FALSE while the GPU works; a removed device answers with its error, and waits no more.
    while (context_->GetData(finished.Get(), &signalled, sizeof signalled, 0) == S_FALSE) Sleep(1);
}

std::string Device::describe() const {
    return adapterName_ + " (feature level " + featureLevelName(featureLevel_) + ") through " + implementationName(implementation_) +
           (warpNotAvailable_ ? ", which has no WARP device: its first adapter" : "");
}

}  // namespace firmament
