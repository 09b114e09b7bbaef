#include "scene/OrientationGridPass.h"

#include "gpu/Hresult.h"

namespace firmament {

namespace {
const ShaderKey kVertexShader{"scene/orientation_grid.hlsl", "vs_main", "vs_5_0", {}};
const ShaderKey kPixelShader{"scene/orientation_grid.hlsl", "ps_main", "ps_5_0", {}};
const ShaderKey kGroundPixelShader{"scene/orientation_grid.hlsl", "ps_main", "ps_5_0", {"GROUND_ONLY=1"}};
}  // namespace

OrientationGridPass::OrientationGridPass(ID3D11Device* device) : fullscreen_(device) {
    D3D11_DEPTH_STENCIL_DESC desc{};
    desc.DepthEnable = TRUE;
    desc.DepthWriteMask = D3D11_DEPTH_WRITE_MASK_ALL;
    desc.DepthFunc = D3D11_COMPARISON_GREATER_EQUAL;  // reversed Z
    check(device->CreateDepthStencilState(&desc, &writeDepth_), "CreateDepthStencilState (orientation grid)");
}

void OrientationGridPass::renderGround(ID3D11DeviceContext* context, ShaderLibrary& shaders, ID3D11Buffer* frameConstants,
                                       ID3D11RenderTargetView* hdrFrame, ID3D11DepthStencilView* depth, int width, int height) {
    fullscreen_.bindTarget(context, hdrFrame, width, height);
    context->OMSetRenderTargets(1, &hdrFrame, depth);
    context->OMSetDepthStencilState(writeDepth_.Get(), 0);
    context->PSSetConstantBuffers(0, 1, &frameConstants);
    fullscreen_.draw(context, shaders, kVertexShader, kGroundPixelShader);
}

void OrientationGridPass::render(ID3D11DeviceContext* context, ShaderLibrary& shaders, ID3D11Buffer* frameConstants,
                                 ID3D11RenderTargetView* hdrFrame, int width, int height) {
    fullscreen_.bindTarget(context, hdrFrame, width, height);
    context->PSSetConstantBuffers(0, 1, &frameConstants);
    fullscreen_.draw(context, shaders, kVertexShader, kPixelShader);
}

}  // namespace firmament
