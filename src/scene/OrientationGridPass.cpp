#include "scene/OrientationGridPass.h"

namespace firmament {

namespace {
const ShaderKey kVertexShader{"scene/orientation_grid.hlsl", "vs_main", "vs_5_0", {}};
const ShaderKey kPixelShader{"scene/orientation_grid.hlsl", "ps_main", "ps_5_0", {}};
}  // namespace

OrientationGridPass::OrientationGridPass(ID3D11Device* device) : fullscreen_(device) {}

void OrientationGridPass::render(ID3D11DeviceContext* context, ShaderLibrary& shaders, ID3D11Buffer* frameConstants,
                                 ID3D11RenderTargetView* hdrFrame, int width, int height) {
    fullscreen_.bindTarget(context, hdrFrame, width, height);
    context->PSSetConstantBuffers(0, 1, &frameConstants);
    fullscreen_.draw(context, shaders, kVertexShader, kPixelShader);
}

}  // namespace firmament
