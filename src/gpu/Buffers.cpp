#include "gpu/Buffers.h"

#include "gpu/Hresult.h"

#include <string>

namespace firmament {

StructuredBuffer createStructuredBuffer(ID3D11Device* device, unsigned count, unsigned stride, const void* initial, const char* what) {
    D3D11_BUFFER_DESC desc{};
    desc.ByteWidth = count * stride;
    desc.Usage = initial ? D3D11_USAGE_IMMUTABLE : D3D11_USAGE_DEFAULT;
    desc.BindFlags = D3D11_BIND_SHADER_RESOURCE | (initial ? 0u : static_cast<UINT>(D3D11_BIND_UNORDERED_ACCESS));
    desc.MiscFlags = D3D11_RESOURCE_MISC_BUFFER_STRUCTURED;
    desc.StructureByteStride = stride;
    const D3D11_SUBRESOURCE_DATA data{initial, 0, 0};
    StructuredBuffer b;
    check(device->CreateBuffer(&desc, initial ? &data : nullptr, &b.buffer), std::string("CreateBuffer (") + what + ")");
    check(device->CreateShaderResourceView(b.buffer.Get(), nullptr, &b.srv), std::string("CreateShaderResourceView (") + what + ")");
    if (!initial) check(device->CreateUnorderedAccessView(b.buffer.Get(), nullptr, &b.uav), std::string("CreateUnorderedAccessView (") + what + ")");
    return b;
}

IndirectArguments createIndirectArguments(ID3D11Device* device, const char* what) {
    constexpr UINT kCount = 8;
    D3D11_BUFFER_DESC desc{};
    desc.ByteWidth = kCount * sizeof(unsigned);
    desc.Usage = D3D11_USAGE_DEFAULT;
    desc.BindFlags = D3D11_BIND_UNORDERED_ACCESS | D3D11_BIND_SHADER_RESOURCE;
    desc.MiscFlags = D3D11_RESOURCE_MISC_DRAWINDIRECT_ARGS;
    IndirectArguments a;
    check(device->CreateBuffer(&desc, nullptr, &a.buffer), std::string("CreateBuffer (") + what + ")");
    D3D11_UNORDERED_ACCESS_VIEW_DESC uav{};
    uav.Format = DXGI_FORMAT_R32_UINT;
    uav.ViewDimension = D3D11_UAV_DIMENSION_BUFFER;
    uav.Buffer.NumElements = kCount;
    check(device->CreateUnorderedAccessView(a.buffer.Get(), &uav, &a.uav), std::string("CreateUnorderedAccessView (") + what + ")");
    D3D11_SHADER_RESOURCE_VIEW_DESC srv{};
    srv.Format = DXGI_FORMAT_R32_UINT;
    srv.ViewDimension = D3D11_SRV_DIMENSION_BUFFER;
    srv.Buffer.NumElements = kCount;
    check(device->CreateShaderResourceView(a.buffer.Get(), &srv, &a.srv), std::string("CreateShaderResourceView (") + what + ")");
    return a;
}

}  // namespace firmament
