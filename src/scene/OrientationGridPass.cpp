#include "scene/OrientationGridPass.h"

#include "gpu/Hresult.h"

namespace firmament {

namespace {
const ShaderKey kVertexShader{"scene/orientation_grid.hlsl", "vs_main", "vs_5_0", {}};
const ShaderKey kPixelShader{"scene/orientation_grid.hlsl", "ps_main", "ps_5_0", {}};
}  // namespace

OrientationGridPass::OrientationGridPass(ID3D11Device* device) {
    D3D11_RASTERIZER_DESC raster{};
    raster.FillMode = D3D11_FILL_SOLID;
    raster.CullMode = D3D11_CULL_NONE;
    raster.DepthClipEnable = TRUE;
    check(device->CreateRasterizerState(&raster, &rasterizer_), "CreateRasterizerState (orientation grid)");
    D3D11_DEPTH_STENCIL_DESC depth{};
    depth.DepthEnable = FALSE;
    check(device->CreateDepthStencilState(&depth, &noDepth_), "CreateDepthStencilState (orientation grid)");
}

void OrientationGridPass::render(ID3D11DeviceContext* context, ShaderLibrary& shaders, ID3D11Buffer* frameConstants,
                                 ID3D11RenderTargetView* hdrFrame, int width, int height) {
    const D3D11_VIEWPORT viewport{0.0f, 0.0f, static_cast<float>(width), static_cast<float>(height), 0.0f, 1.0f};
    context->OMSetRenderTargets(1, &hdrFrame, nullptr);
    context->OMSetDepthStencilState(noDepth_.Get(), 0);
    context->OMSetBlendState(nullptr, nullptr, 0xffffffff);
    context->RSSetState(rasterizer_.Get());
    context->RSSetViewports(1, &viewport);
    context->IASetInputLayout(nullptr);
    context->IASetPrimitiveTopology(D3D11_PRIMITIVE_TOPOLOGY_TRIANGLELIST);
    context->VSSetShader(shaders.vertexShader(kVertexShader), nullptr, 0);
    context->PSSetShader(shaders.pixelShader(kPixelShader), nullptr, 0);
    context->PSSetConstantBuffers(0, 1, &frameConstants);
    context->Draw(3, 0);
}

}  // namespace firmament
