#include "postfx/ToneMappingPass.h"

namespace firmament {

namespace {
const ShaderKey kVertexShader{"postfx/tone_mapping.hlsl", "vs_main", "vs_5_0", {}};
const ShaderKey kPixelShader{"postfx/tone_mapping.hlsl", "ps_main", "ps_5_0", {}};
}  // namespace

ToneMappingPass::ToneMappingPass(ID3D11Device* device) : fullscreen_(device), constants_(device) {}

void ToneMappingPass::render(ID3D11DeviceContext* context, ShaderLibrary& shaders, const ToneMappingSettings& settings,
                             ID3D11ShaderResourceView* hdrFrame, ID3D11ShaderResourceView* adaptedLogLuminance,
                             ID3D11RenderTargetView* output, int width, int height) {
    gpu::ToneMappingConstants constants{};
    constants.mode = glm::uvec4(static_cast<unsigned>(settings.op), settings.autoExposure ? 1u : 0u, 0u, 0u);
    constants.exposure = glm::vec4(settings.middleGray, settings.exposureCompensation(), settings.whitePoint,
                                   settings.luminanceSaturation);
    constants_.update(context, constants);
    fullscreen_.bindTarget(context, output, width, height);
    context->PSSetConstantBuffers(0, 1, constants_.address());
    ID3D11ShaderResourceView* inputs[2] = {hdrFrame, adaptedLogLuminance};
    context->PSSetShaderResources(0, 2, inputs);
    fullscreen_.draw(context, shaders, kVertexShader, kPixelShader);
    ID3D11ShaderResourceView* none[2] = {nullptr, nullptr};
    context->PSSetShaderResources(0, 2, none);
}

}  // namespace firmament
