#include "gpu/CountingDevice.h"

namespace firmament {

CountingDevice::CountingDevice(ID3D11Device* driver, LiveObjectCounter counter) : driver_(driver), counter_(std::move(counter)) {}

HRESULT CountingDevice::QueryInterface(REFIID riid, void** object) {
    if (!object) return E_POINTER;
    if (riid == __uuidof(ID3D11Device) || riid == __uuidof(IUnknown)) {
        *object = static_cast<ID3D11Device*>(this);
        AddRef();
        return S_OK;
    }
    return driver_->QueryInterface(riid, object);
}

ULONG CountingDevice::AddRef() { return ++references_; }

ULONG CountingDevice::Release() {
    const ULONG left = --references_;
    if (left == 0) delete this;
    return left;
}

HRESULT CountingDevice::CreateBuffer(const D3D11_BUFFER_DESC* desc, const D3D11_SUBRESOURCE_DATA* data, ID3D11Buffer** out) {
    return counted(driver_->CreateBuffer(desc, data, out), out, GpuObjectKind::Buffer);
}
HRESULT CountingDevice::CreateTexture1D(const D3D11_TEXTURE1D_DESC* desc, const D3D11_SUBRESOURCE_DATA* data, ID3D11Texture1D** out) {
    return counted(driver_->CreateTexture1D(desc, data, out), out, GpuObjectKind::Texture);
}
HRESULT CountingDevice::CreateTexture2D(const D3D11_TEXTURE2D_DESC* desc, const D3D11_SUBRESOURCE_DATA* data, ID3D11Texture2D** out) {
    return counted(driver_->CreateTexture2D(desc, data, out), out, GpuObjectKind::Texture);
}
HRESULT CountingDevice::CreateTexture3D(const D3D11_TEXTURE3D_DESC* desc, const D3D11_SUBRESOURCE_DATA* data, ID3D11Texture3D** out) {
    return counted(driver_->CreateTexture3D(desc, data, out), out, GpuObjectKind::Texture);
}
HRESULT CountingDevice::CreateShaderResourceView(ID3D11Resource* resource, const D3D11_SHADER_RESOURCE_VIEW_DESC* desc,
                                                 ID3D11ShaderResourceView** out) {
    return counted(driver_->CreateShaderResourceView(resource, desc, out), out, GpuObjectKind::View);
}
HRESULT CountingDevice::CreateUnorderedAccessView(ID3D11Resource* resource, const D3D11_UNORDERED_ACCESS_VIEW_DESC* desc,
                                                  ID3D11UnorderedAccessView** out) {
    return counted(driver_->CreateUnorderedAccessView(resource, desc, out), out, GpuObjectKind::View);
}
HRESULT CountingDevice::CreateRenderTargetView(ID3D11Resource* resource, const D3D11_RENDER_TARGET_VIEW_DESC* desc, ID3D11RenderTargetView** out) {
    return counted(driver_->CreateRenderTargetView(resource, desc, out), out, GpuObjectKind::View);
}
HRESULT CountingDevice::CreateDepthStencilView(ID3D11Resource* resource, const D3D11_DEPTH_STENCIL_VIEW_DESC* desc, ID3D11DepthStencilView** out) {
    return counted(driver_->CreateDepthStencilView(resource, desc, out), out, GpuObjectKind::View);
}
HRESULT CountingDevice::CreateInputLayout(const D3D11_INPUT_ELEMENT_DESC* elements, UINT count, const void* bytecode, SIZE_T size,
                                          ID3D11InputLayout** out) {
    return counted(driver_->CreateInputLayout(elements, count, bytecode, size, out), out, GpuObjectKind::InputLayout);
}
HRESULT CountingDevice::CreateVertexShader(const void* bytecode, SIZE_T size, ID3D11ClassLinkage* linkage, ID3D11VertexShader** out) {
    return counted(driver_->CreateVertexShader(bytecode, size, linkage, out), out, GpuObjectKind::Shader);
}
HRESULT CountingDevice::CreateGeometryShader(const void* bytecode, SIZE_T size, ID3D11ClassLinkage* linkage, ID3D11GeometryShader** out) {
    return counted(driver_->CreateGeometryShader(bytecode, size, linkage, out), out, GpuObjectKind::Shader);
}
HRESULT CountingDevice::CreateGeometryShaderWithStreamOutput(const void* bytecode, SIZE_T size, const D3D11_SO_DECLARATION_ENTRY* entries,
                                                             UINT entryCount, const UINT* strides, UINT strideCount, UINT rasterizedStream,
                                                             ID3D11ClassLinkage* linkage, ID3D11GeometryShader** out) {
    return counted(driver_->CreateGeometryShaderWithStreamOutput(bytecode, size, entries, entryCount, strides, strideCount, rasterizedStream,
                                                                 linkage, out),
                   out, GpuObjectKind::Shader);
}
HRESULT CountingDevice::CreatePixelShader(const void* bytecode, SIZE_T size, ID3D11ClassLinkage* linkage, ID3D11PixelShader** out) {
    return counted(driver_->CreatePixelShader(bytecode, size, linkage, out), out, GpuObjectKind::Shader);
}
HRESULT CountingDevice::CreateHullShader(const void* bytecode, SIZE_T size, ID3D11ClassLinkage* linkage, ID3D11HullShader** out) {
    return counted(driver_->CreateHullShader(bytecode, size, linkage, out), out, GpuObjectKind::Shader);
}
HRESULT CountingDevice::CreateDomainShader(const void* bytecode, SIZE_T size, ID3D11ClassLinkage* linkage, ID3D11DomainShader** out) {
    return counted(driver_->CreateDomainShader(bytecode, size, linkage, out), out, GpuObjectKind::Shader);
}
HRESULT CountingDevice::CreateComputeShader(const void* bytecode, SIZE_T size, ID3D11ClassLinkage* linkage, ID3D11ComputeShader** out) {
    return counted(driver_->CreateComputeShader(bytecode, size, linkage, out), out, GpuObjectKind::Shader);
}
HRESULT CountingDevice::CreateClassLinkage(ID3D11ClassLinkage** out) {
    return counted(driver_->CreateClassLinkage(out), out, GpuObjectKind::Other);
}
HRESULT CountingDevice::CreateBlendState(const D3D11_BLEND_DESC* desc, ID3D11BlendState** out) {
    return counted(driver_->CreateBlendState(desc, out), out, GpuObjectKind::State);
}
HRESULT CountingDevice::CreateDepthStencilState(const D3D11_DEPTH_STENCIL_DESC* desc, ID3D11DepthStencilState** out) {
    return counted(driver_->CreateDepthStencilState(desc, out), out, GpuObjectKind::State);
}
HRESULT CountingDevice::CreateRasterizerState(const D3D11_RASTERIZER_DESC* desc, ID3D11RasterizerState** out) {
    return counted(driver_->CreateRasterizerState(desc, out), out, GpuObjectKind::State);
}
HRESULT CountingDevice::CreateSamplerState(const D3D11_SAMPLER_DESC* desc, ID3D11SamplerState** out) {
    return counted(driver_->CreateSamplerState(desc, out), out, GpuObjectKind::State);
}
HRESULT CountingDevice::CreateQuery(const D3D11_QUERY_DESC* desc, ID3D11Query** out) {
    return counted(driver_->CreateQuery(desc, out), out, GpuObjectKind::Query);
}
HRESULT CountingDevice::CreatePredicate(const D3D11_QUERY_DESC* desc, ID3D11Predicate** out) {
    return counted(driver_->CreatePredicate(desc, out), out, GpuObjectKind::Query);
}
HRESULT CountingDevice::CreateCounter(const D3D11_COUNTER_DESC* desc, ID3D11Counter** out) {
    return counted(driver_->CreateCounter(desc, out), out, GpuObjectKind::Query);
}
HRESULT CountingDevice::CreateDeferredContext(UINT flags, ID3D11DeviceContext** out) {
    return counted(driver_->CreateDeferredContext(flags, out), out, GpuObjectKind::Other);
}

HRESULT CountingDevice::OpenSharedResource(HANDLE resource, REFIID riid, void** out) { return driver_->OpenSharedResource(resource, riid, out); }
HRESULT CountingDevice::CheckFormatSupport(DXGI_FORMAT format, UINT* support) { return driver_->CheckFormatSupport(format, support); }
HRESULT CountingDevice::CheckMultisampleQualityLevels(DXGI_FORMAT format, UINT samples, UINT* levels) {
    return driver_->CheckMultisampleQualityLevels(format, samples, levels);
}
void CountingDevice::CheckCounterInfo(D3D11_COUNTER_INFO* info) { driver_->CheckCounterInfo(info); }
HRESULT CountingDevice::CheckCounter(const D3D11_COUNTER_DESC* desc, D3D11_COUNTER_TYPE* type, UINT* activeCounters, LPSTR name, UINT* nameLength,
                                     LPSTR units, UINT* unitsLength, LPSTR description, UINT* descriptionLength) {
    return driver_->CheckCounter(desc, type, activeCounters, name, nameLength, units, unitsLength, description, descriptionLength);
}
HRESULT CountingDevice::CheckFeatureSupport(D3D11_FEATURE feature, void* data, UINT size) { return driver_->CheckFeatureSupport(feature, data, size); }
HRESULT CountingDevice::GetPrivateData(REFGUID guid, UINT* size, void* data) { return driver_->GetPrivateData(guid, size, data); }
HRESULT CountingDevice::SetPrivateData(REFGUID guid, UINT size, const void* data) { return driver_->SetPrivateData(guid, size, data); }
HRESULT CountingDevice::SetPrivateDataInterface(REFGUID guid, const IUnknown* data) { return driver_->SetPrivateDataInterface(guid, data); }
D3D_FEATURE_LEVEL CountingDevice::GetFeatureLevel() { return driver_->GetFeatureLevel(); }
UINT CountingDevice::GetCreationFlags() { return driver_->GetCreationFlags(); }
HRESULT CountingDevice::GetDeviceRemovedReason() { return driver_->GetDeviceRemovedReason(); }
void CountingDevice::GetImmediateContext(ID3D11DeviceContext** out) { driver_->GetImmediateContext(out); }
HRESULT CountingDevice::SetExceptionMode(UINT flags) { return driver_->SetExceptionMode(flags); }
UINT CountingDevice::GetExceptionMode() { return driver_->GetExceptionMode(); }

}  // namespace firmament
