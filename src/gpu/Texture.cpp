#include "gpu/Texture.h"

#include "gpu/Hresult.h"

namespace firmament {

namespace {
// One mip level, one slice, no multisampling: what every frame target is.
Texture2D createTexture(ID3D11Device* device, int width, int height, DXGI_FORMAT format, UINT bindFlags, const char* what) {
    Texture2D t;
    t.width = width;
    t.height = height;
    t.format = format;
    D3D11_TEXTURE2D_DESC desc{};
    desc.Width = static_cast<UINT>(width);
    desc.Height = static_cast<UINT>(height);
    desc.MipLevels = 1;
    desc.ArraySize = 1;
    desc.Format = format;
    desc.SampleDesc.Count = 1;
    desc.Usage = D3D11_USAGE_DEFAULT;
    desc.BindFlags = bindFlags;
    check(device->CreateTexture2D(&desc, nullptr, &t.texture), what);
    return t;
}
}  // namespace

Texture2D createColorTexture(ID3D11Device* device, int width, int height, DXGI_FORMAT format, UINT bindFlags) {
    Texture2D t = createTexture(device, width, height, format, bindFlags, "CreateTexture2D (colour)");
    if (bindFlags & D3D11_BIND_RENDER_TARGET)
        check(device->CreateRenderTargetView(t.texture.Get(), nullptr, &t.rtv), "CreateRenderTargetView");
    if (bindFlags & D3D11_BIND_SHADER_RESOURCE)
        check(device->CreateShaderResourceView(t.texture.Get(), nullptr, &t.srv), "CreateShaderResourceView");
    if (bindFlags & D3D11_BIND_UNORDERED_ACCESS)
        check(device->CreateUnorderedAccessView(t.texture.Get(), nullptr, &t.uav), "CreateUnorderedAccessView");
    return t;
}

Texture3D createTexture3D(ID3D11Device* device, int width, int height, int depth, DXGI_FORMAT format, UINT bindFlags) {
    Texture3D t;
    t.width = width;
    t.height = height;
    t.depth = depth;
    D3D11_TEXTURE3D_DESC desc{};
    desc.Width = static_cast<UINT>(width);
    desc.Height = static_cast<UINT>(height);
    desc.Depth = static_cast<UINT>(depth);
    desc.MipLevels = 1;
    desc.Format = format;
    desc.Usage = D3D11_USAGE_DEFAULT;
    desc.BindFlags = bindFlags;
    check(device->CreateTexture3D(&desc, nullptr, &t.texture), "CreateTexture3D");
    if (bindFlags & D3D11_BIND_SHADER_RESOURCE)
        check(device->CreateShaderResourceView(t.texture.Get(), nullptr, &t.srv), "CreateShaderResourceView (3D)");
    if (bindFlags & D3D11_BIND_UNORDERED_ACCESS)
        check(device->CreateUnorderedAccessView(t.texture.Get(), nullptr, &t.uav), "CreateUnorderedAccessView (3D)");
    return t;
}

Texture2D createDepthTexture(ID3D11Device* device, int width, int height) {
    Texture2D t = createTexture(device, width, height, DXGI_FORMAT_R32_TYPELESS,
                                D3D11_BIND_DEPTH_STENCIL | D3D11_BIND_SHADER_RESOURCE, "CreateTexture2D (depth)");

    D3D11_DEPTH_STENCIL_VIEW_DESC dsvDesc{};
    dsvDesc.Format = DXGI_FORMAT_D32_FLOAT;
    dsvDesc.ViewDimension = D3D11_DSV_DIMENSION_TEXTURE2D;
    check(device->CreateDepthStencilView(t.texture.Get(), &dsvDesc, &t.dsv), "CreateDepthStencilView");

    D3D11_SHADER_RESOURCE_VIEW_DESC srvDesc{};
    srvDesc.Format = DXGI_FORMAT_R32_FLOAT;
    srvDesc.ViewDimension = D3D11_SRV_DIMENSION_TEXTURE2D;
    srvDesc.Texture2D.MipLevels = 1;
    check(device->CreateShaderResourceView(t.texture.Get(), &srvDesc, &t.srv), "CreateShaderResourceView (depth)");
    return t;
}

}  // namespace firmament
