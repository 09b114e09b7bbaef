#include "atmosphere/ScatteringPass.h"

#include <cmath>

namespace firmament {

namespace {
const ShaderKey kVertexShader{"atmosphere/apply_scattering.hlsl", "vs_main", "vs_5_0", {}};
const ShaderKey kPixelShader{"atmosphere/apply_scattering.hlsl", "ps_main", "ps_5_0", {}};
constexpr double kPi = 3.14159265358979323846;
}  // namespace

double ScatteringPass::sunDiscRadiance() { return 1.0 / (2.0 * kPi * (1.0 - std::cos(kSunAngularRadius))); }

ScatteringPass::ScatteringPass(ID3D11Device* device)
    : fullscreen_(device), atmosphere_(device), constants_(device), linearClamp_(createLinearClampSampler(device)) {}

void ScatteringPass::render(ID3D11DeviceContext* context, ShaderLibrary& shaders, const AtmosphereSettings& settings,
                            const AtmosphereParameters& parameters, const ScatteringTables& tables, ID3D11Buffer* frameConstants,
                            ID3D11ShaderResourceView* sceneRadiance, ID3D11ShaderResourceView* depth, const Texture2D& target) {

    atmosphere_.update(context, parameters.constants());
    gpu::ScatteringPassConstants constants{};
    constants.mode = glm::uvec4(static_cast<unsigned>(settings.singleScattering), static_cast<unsigned>(settings.integrationSteps),
                                static_cast<unsigned>(settings.multipleScattering), 0u);
    constants.sun = glm::vec4(static_cast<float>(std::cos(kSunAngularRadius)), static_cast<float>(sunDiscRadiance()), 0.0f, 0.0f);
    constants_.update(context, constants);

    fullscreen_.bindTarget(context, target.rtv.Get(), target.width, target.height);
    ID3D11Buffer* buffers[3] = {frameConstants, atmosphere_.get(), constants_.get()};
    context->PSSetConstantBuffers(0, 3, buffers);
    ID3D11ShaderResourceView* inputs[6] = {sceneRadiance,          depth, tables.netDensity.srv.Get(), tables.singleScattering.srv.Get(),
                                           tables.highOrderScattering.srv.Get(), tables.multipleScattering.srv.Get()};
    context->PSSetShaderResources(0, 6, inputs);
    context->PSSetSamplers(0, 1, linearClamp_.GetAddressOf());
    fullscreen_.draw(context, shaders, kVertexShader, kPixelShader);
    ID3D11ShaderResourceView* none[6] = {};
    context->PSSetShaderResources(0, 6, none);
}

}  // namespace firmament
