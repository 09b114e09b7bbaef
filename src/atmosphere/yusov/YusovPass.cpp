#include "atmosphere/yusov/YusovPass.h"

#include "atmosphere/SunDisc.h"
#include "gpu/CommonStates.h"

namespace firmament {

namespace {
const std::string kShaderFile = "atmosphere/yusov/render.hlsl";
}  // namespace

YusovPass::YusovPass(ID3D11Device* device)
    : fullscreen_(device), atmosphere_(device), constants_(device), linearClamp_(states::linearClamp(device)) {}

gpu::YusovPassConstants YusovPass::constants(const AtmosphereSettings& settings) {
    gpu::YusovPassConstants c{};
    c.mode = glm::uvec4(static_cast<unsigned>(settings.singleScattering), static_cast<unsigned>(settings.integrationSteps),
                        static_cast<unsigned>(settings.multipleScattering), 0u);
    c.sun = sunDiscConstants();
    return c;
}

void YusovPass::render(ID3D11DeviceContext* context, ShaderLibrary& shaders, AtmospherePart part, const AtmosphereSettings& settings,
                       const YusovPrecomputation& tables, ID3D11Buffer* frameConstants, ID3D11ShaderResourceView* sceneRadiance,
                       ID3D11ShaderResourceView* depth, const Texture2D& target, Columns columns) {
    atmosphere_.update(context, tables.parameters().constants());
    constants_.update(context, constants(settings));
    fullscreen_.bindTarget(context, target.rtv.Get(), target.width, target.height, columns);
    const YusovTables& t = tables.tables();
    fullscreen_.draw(context, shaders, atmosphereVertexShader(kShaderFile), atmospherePixelShader(kShaderFile, part),
                     {frameConstants, atmosphere_.get(), constants_.get()},
                     {sceneRadiance, depth, t.netDensity.srv.Get(), t.singleScattering.srv.Get(), t.highOrderScattering.srv.Get(),
                      t.multipleScattering.srv.Get()},
                     linearClamp_.Get());
}

}  // namespace firmament
