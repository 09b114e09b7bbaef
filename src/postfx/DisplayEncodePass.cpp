#include "postfx/DisplayEncodePass.h"

#include "gpu/Hresult.h"

namespace firmament {

namespace {
const ShaderKey kVertexShader{"postfx/display_encode.hlsl", "vs_main", "vs_5_0", {}};
const ShaderKey kPixelShader{"postfx/display_encode.hlsl", "ps_main", "ps_5_0", {}};
}  // namespace

DisplayEncodePass::DisplayEncodePass(ID3D11Device* device) : constants_(device) {
    D3D11_RASTERIZER_DESC raster{};
    raster.FillMode = D3D11_FILL_SOLID;
    raster.CullMode = D3D11_CULL_NONE;
    raster.DepthClipEnable = TRUE;
    check(device->CreateRasterizerState(&raster, &rasterizer_), "CreateRasterizerState (display encode)");
    D3D11_DEPTH_STENCIL_DESC depth{};
    depth.DepthEnable = FALSE;
    check(device->CreateDepthStencilState(&depth, &noDepth_), "CreateDepthStencilState (display encode)");
}

void DisplayEncodePass::render(ID3D11DeviceContext* context, ShaderLibrary& shaders, const ToneMappingSettings& settings,
                               ID3D11ShaderResourceView* hdrFrame, ID3D11RenderTargetView* output, int width, int height) {
    gpu::DisplayEncodeConstants constants{};
    constants.exposure.x = settings.exposureScale();
    constants_.update(context, constants);
    const D3D11_VIEWPORT viewport{0.0f, 0.0f, static_cast<float>(width), static_cast<float>(height), 0.0f, 1.0f};
    context->OMSetRenderTargets(1, &output, nullptr);
    context->OMSetDepthStencilState(noDepth_.Get(), 0);
    context->OMSetBlendState(nullptr, nullptr, 0xffffffff);
    context->RSSetState(rasterizer_.Get());
    context->RSSetViewports(1, &viewport);
    context->IASetInputLayout(nullptr);
    context->IASetPrimitiveTopology(D3D11_PRIMITIVE_TOPOLOGY_TRIANGLELIST);
    context->VSSetShader(shaders.vertexShader(kVertexShader), nullptr, 0);
    context->PSSetShader(shaders.pixelShader(kPixelShader), nullptr, 0);
    context->PSSetConstantBuffers(0, 1, constants_.address());
    context->PSSetShaderResources(0, 1, &hdrFrame);
    context->Draw(3, 0);
    ID3D11ShaderResourceView* none = nullptr;
    context->PSSetShaderResources(0, 1, &none);
}

}  // namespace firmament
