#include "gpu/WorkList.h"

#include "gpu/Hresult.h"

namespace firmament {

WorkList::WorkList(ID3D11Device* device, unsigned capacity) : capacity_(capacity > 0 ? capacity : 1) {
    D3D11_BUFFER_DESC items{};
    items.ByteWidth = capacity_ * sizeof(unsigned);
    items.Usage = D3D11_USAGE_DEFAULT;
    items.BindFlags = D3D11_BIND_UNORDERED_ACCESS | D3D11_BIND_SHADER_RESOURCE;
    items.MiscFlags = D3D11_RESOURCE_MISC_BUFFER_STRUCTURED;
    items.StructureByteStride = sizeof(unsigned);
    check(device->CreateBuffer(&items, nullptr, &items_), "CreateBuffer (work list)");
    check(device->CreateUnorderedAccessView(items_.Get(), nullptr, &itemsUav_), "CreateUnorderedAccessView (work list)");
    check(device->CreateShaderResourceView(items_.Get(), nullptr, &itemsSrv_), "CreateShaderResourceView (work list)");

    D3D11_BUFFER_DESC arguments{};
    arguments.ByteWidth = 8 * sizeof(unsigned);
    arguments.Usage = D3D11_USAGE_DEFAULT;
    arguments.BindFlags = D3D11_BIND_UNORDERED_ACCESS | D3D11_BIND_SHADER_RESOURCE;
    arguments.MiscFlags = D3D11_RESOURCE_MISC_DRAWINDIRECT_ARGS;
    check(device->CreateBuffer(&arguments, nullptr, &arguments_), "CreateBuffer (work list arguments)");
    D3D11_UNORDERED_ACCESS_VIEW_DESC uav{};
    uav.Format = DXGI_FORMAT_R32_UINT;
    uav.ViewDimension = D3D11_UAV_DIMENSION_BUFFER;
    uav.Buffer.NumElements = 8;
    check(device->CreateUnorderedAccessView(arguments_.Get(), &uav, &argumentsUav_), "CreateUnorderedAccessView (work list arguments)");
    D3D11_SHADER_RESOURCE_VIEW_DESC srv{};
    srv.Format = DXGI_FORMAT_R32_UINT;
    srv.ViewDimension = D3D11_SRV_DIMENSION_BUFFER;
    srv.Buffer.NumElements = 8;
    check(device->CreateShaderResourceView(arguments_.Get(), &srv, &argumentsSrv_), "CreateShaderResourceView (work list arguments)");
}

void WorkList::clear(ID3D11DeviceContext* context) const {
    const UINT zero[4] = {0, 0, 0, 0};
    context->ClearUnorderedAccessViewUint(argumentsUav_.Get(), zero);
}

void WorkList::dispatch(ID3D11DeviceContext* context, bool layered) const {
    context->DispatchIndirect(arguments_.Get(), layered ? 4 * sizeof(unsigned) : 0);
}

}  // namespace firmament
