#pragma once
// The Direct3D 11 device and its immediate context, created as DeviceOptions asks. The device
// the program is given counts the objects it makes (CountingDevice).
#include "core/Text.h"
#include "gpu/D3D11Implementation.h"
#include "gpu/DeviceOptions.h"
#include "gpu/LiveObjects.h"

#include <d3d11_1.h>
#include <dxgi1_5.h>
#include <wrl/client.h>

#include <string>

namespace firmament {

using Microsoft::WRL::ComPtr;

class Device {
public:
    explicit Device(const DeviceOptions& options);  // throws Error

    ID3D11Device* device() const { return device_.Get(); }  // counts what it makes
    ID3D11Device* driverDevice() const { return driver_.Get(); }  // the driver's own, for DXGI
    ID3D11DeviceContext* context() const { return context_.Get(); }
    IDXGIFactory2* factory() const { return factory_.Get(); }

    const std::string& adapterName() const { return adapterName_; }
    D3D_FEATURE_LEVEL featureLevel() const { return featureLevel_; }
    bool tearingSupported() const { return tearingSupported_; }
    D3D11Implementation implementation() const { return implementation_; }
    // "adapter (feature level 11_1) through implementation", and where a WARP device was asked of
    // DXVK, which has none, that its first adapter was taken.
    std::string describe() const;
    // Empty while the device works; after DXGI_ERROR_DEVICE_REMOVED, _RESET, _HUNG and the like,
    // why (ID3D11Device::GetDeviceRemovedReason, named).
    std::string removedReason() const;
    // The objects made through device() that are alive, once the GPU has finished the work sent
    // so far (objects are destroyed on the driver's thread after their last Release).
    LiveObjectCounts liveObjects() const;
    // Returns once the GPU has finished the work sent so far (or the device is removed).
    void waitForGpu() const;

private:
    ComPtr<IDXGIFactory2> factory_;
    ComPtr<ID3D11Device> driver_;
    LiveObjectCounter liveObjects_;
    ComPtr<ID3D11Device> device_;  // a CountingDevice over driver_
    ComPtr<ID3D11DeviceContext> context_;
    std::string adapterName_;
    D3D_FEATURE_LEVEL featureLevel_ = D3D_FEATURE_LEVEL_11_0;
    bool tearingSupported_ = false;
    D3D11Implementation implementation_ = D3D11Implementation::Windows;
    bool warpNotAvailable_ = false;
};

std::string featureLevelName(D3D_FEATURE_LEVEL level);
// "DXGI_ERROR_DEVICE_REMOVED", ... for the HRESULTs that mean the device is gone; else the code in hex.
std::string deviceLossName(HRESULT hr);

}  // namespace firmament
