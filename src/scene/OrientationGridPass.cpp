#include "scene/OrientationGridPass.h"

#include "gpu/CommonStates.h"

namespace firmament {

namespace {
const ShaderKey kVertexShader{"scene/orientation_grid.hlsl", "vs_main", "vs_5_0", {}};
const ShaderKey kPixelShader{"scene/orientation_grid.hlsl", "ps_main", "ps_5_0", {}};
const ShaderKey kGroundPixelShader{"scene/orientation_grid.hlsl", "ps_main", "ps_5_0", {"GROUND_ONLY=1"}};
}  // namespace

OrientationGridPass::OrientationGridPass(ID3D11Device* device) : fullscreen_(device), writeDepth_(states::depthReversed(device)) {}

void OrientationGridPass::render(FrameContext& frame, bool groundOnly) {
    ID3D11DeviceContext* context = frame.context;
    ID3D11RenderTargetView* hdr = frame.targets.hdr().rtv.Get();
    fullscreen_.bindTarget(context, hdr, frame.width(), frame.height());
    if (groundOnly) {
        context->OMSetRenderTargets(1, &hdr, frame.targets.depth().dsv.Get());
        context->OMSetDepthStencilState(writeDepth_.Get(), 0);
    }
    context->PSSetConstantBuffers(0, 1, &frame.frameConstants);
    fullscreen_.draw(context, frame.shaders, kVertexShader, groundOnly ? kGroundPixelShader : kPixelShader);
}

}  // namespace firmament
