#include "postfx/DisplayEncodePass.h"

namespace firmament {

namespace {
const ShaderKey kVertexShader{"postfx/display_encode.hlsl", "vs_main", "vs_5_0", {}};
const ShaderKey kPixelShader{"postfx/display_encode.hlsl", "ps_main", "ps_5_0", {}};
}  // namespace

DisplayEncodePass::DisplayEncodePass(ID3D11Device* device) : fullscreen_(device), constants_(device) {}

void DisplayEncodePass::render(ID3D11DeviceContext* context, ShaderLibrary& shaders, const ToneMappingSettings& settings,
                               ID3D11ShaderResourceView* hdrFrame, ID3D11RenderTargetView* output, int width, int height) {
    gpu::DisplayEncodeConstants constants{};
    constants.exposure.x = settings.exposureScale();
    constants_.update(context, constants);
    fullscreen_.bindTarget(context, output, width, height);
    context->PSSetConstantBuffers(0, 1, constants_.address());
    context->PSSetShaderResources(0, 1, &hdrFrame);
    fullscreen_.draw(context, shaders, kVertexShader, kPixelShader);
    ID3D11ShaderResourceView* none = nullptr;
    context->PSSetShaderResources(0, 1, &none);
}

}  // namespace firmament
