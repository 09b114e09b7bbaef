#include "atmosphere/yusov/YusovPass.h"

#include "atmosphere/SunDisc.h"
#include "gpu/CommonStates.h"

#include <cmath>

namespace firmament {

namespace {
const ShaderKey kVertexShader{"atmosphere/yusov/render.hlsl", "vs_main", "vs_5_0", {}};
const ShaderKey kSkyShader{"atmosphere/yusov/render.hlsl", "ps_sky", "ps_5_0", {}};
const ShaderKey kAerialPerspectiveShader{"atmosphere/yusov/render.hlsl", "ps_aerial_perspective", "ps_5_0", {}};
}  // namespace

YusovPass::YusovPass(ID3D11Device* device)
    : fullscreen_(device), atmosphere_(device), constants_(device), linearClamp_(states::linearClamp(device)) {}

gpu::YusovPassConstants YusovPass::constants(const AtmosphereSettings& settings) {
    gpu::YusovPassConstants c{};
    c.mode = glm::uvec4(static_cast<unsigned>(settings.singleScattering), static_cast<unsigned>(settings.integrationSteps),
                        static_cast<unsigned>(settings.multipleScattering), 0u);
    c.sun = glm::vec4(static_cast<float>(std::cos(kSunAngularRadius)), static_cast<float>(sunDiscRadiance()), 0.0f, 0.0f);
    return c;
}

void YusovPass::renderSky(ID3D11DeviceContext* context, ShaderLibrary& shaders, const AtmosphereSettings& settings,
                          const YusovPrecomputation& tables, ID3D11Buffer* frameConstants, ID3D11ShaderResourceView* depth,
                          const Texture2D& target) {
    draw(context, shaders, kSkyShader, settings, tables, frameConstants, nullptr, depth, target);
}

void YusovPass::renderAerialPerspective(ID3D11DeviceContext* context, ShaderLibrary& shaders, const AtmosphereSettings& settings,
                                        const YusovPrecomputation& tables, ID3D11Buffer* frameConstants,
                                        ID3D11ShaderResourceView* sceneRadiance, ID3D11ShaderResourceView* depth, const Texture2D& target) {
    draw(context, shaders, kAerialPerspectiveShader, settings, tables, frameConstants, sceneRadiance, depth, target);
}

void YusovPass::draw(ID3D11DeviceContext* context, ShaderLibrary& shaders, const ShaderKey& pixelShader, const AtmosphereSettings& settings,
                     const YusovPrecomputation& tables, ID3D11Buffer* frameConstants, ID3D11ShaderResourceView* sceneRadiance,
                     ID3D11ShaderResourceView* depth, const Texture2D& target) {
    atmosphere_.update(context, tables.parameters().constants());
    constants_.update(context, constants(settings));
    fullscreen_.bindTarget(context, target.rtv.Get(), target.width, target.height);
    ID3D11Buffer* buffers[3] = {frameConstants, atmosphere_.get(), constants_.get()};
    context->PSSetConstantBuffers(0, 3, buffers);
    const YusovTables& t = tables.tables();
    ID3D11ShaderResourceView* inputs[6] = {sceneRadiance, depth, t.netDensity.srv.Get(), t.singleScattering.srv.Get(),
                                           t.highOrderScattering.srv.Get(), t.multipleScattering.srv.Get()};
    context->PSSetShaderResources(0, 6, inputs);
    context->PSSetSamplers(0, 1, linearClamp_.GetAddressOf());
    fullscreen_.draw(context, shaders, kVertexShader, pixelShader);
    ID3D11ShaderResourceView* none[6] = {};
    context->PSSetShaderResources(0, 6, none);
}

}  // namespace firmament
