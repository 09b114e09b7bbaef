#include "atmosphere/bruneton/BrunetonPass.h"

#include "atmosphere/SunDisc.h"
#include "gpu/CommonStates.h"

#include <cmath>

namespace firmament {

namespace {
const ShaderKey kVertexShader{"atmosphere/bruneton/render.hlsl", "vs_main", "vs_5_0", {}};
const ShaderKey kSkyShader{"atmosphere/bruneton/render.hlsl", "ps_sky", "ps_5_0", {}};
const ShaderKey kAerialPerspectiveShader{"atmosphere/bruneton/render.hlsl", "ps_aerial_perspective", "ps_5_0", {}};
}  // namespace

BrunetonPass::BrunetonPass(ID3D11Device* device)
    : fullscreen_(device), atmosphere_(device), bruneton_(device), constants_(device), linearClamp_(states::linearClamp(device)) {}

void BrunetonPass::renderSky(ID3D11DeviceContext* context, ShaderLibrary& shaders, const BrunetonPrecomputation& tables,
                             ID3D11Buffer* frameConstants, ID3D11ShaderResourceView* depth, const Texture2D& target,
                             const BrunetonComposition& composition) {
    draw(context, shaders, kSkyShader, tables, frameConstants, nullptr, depth, target, composition);
}

void BrunetonPass::renderAerialPerspective(ID3D11DeviceContext* context, ShaderLibrary& shaders, const BrunetonPrecomputation& tables,
                                           ID3D11Buffer* frameConstants, ID3D11ShaderResourceView* sceneRadiance,
                                           ID3D11ShaderResourceView* depth, const Texture2D& target, const BrunetonComposition& composition) {
    draw(context, shaders, kAerialPerspectiveShader, tables, frameConstants, sceneRadiance, depth, target, composition);
}

void BrunetonPass::draw(ID3D11DeviceContext* context, ShaderLibrary& shaders, const ShaderKey& pixelShader, const BrunetonPrecomputation& tables,
                        ID3D11Buffer* frameConstants, ID3D11ShaderResourceView* sceneRadiance, ID3D11ShaderResourceView* depth,
                        const Texture2D& target, const BrunetonComposition& composition) {
    atmosphere_.update(context, tables.parameters().physics.constants());
    bruneton_.update(context, tables.parameters().constants());
    gpu::BrunetonPassConstants constants{};
    constants.view = glm::uvec4(static_cast<unsigned>(composition.view), composition.firstColumn, 0u, 0u);
    // The same sun disc as Yusov's model draws, so that the two compare.
    constants.sun = glm::vec4(static_cast<float>(std::cos(kSunAngularRadius)), static_cast<float>(sunDiscRadiance()), 0.0f, 0.0f);
    constants_.update(context, constants);

    fullscreen_.bindTarget(context, target.rtv.Get(), target.width, target.height);
    ID3D11Buffer* buffers[4] = {frameConstants, atmosphere_.get(), bruneton_.get(), constants_.get()};
    context->PSSetConstantBuffers(0, 4, buffers);
    const BrunetonTables& t = tables.tables();
    ID3D11ShaderResourceView* inputs[6] = {sceneRadiance, depth, t.transmittance.srv.Get(), t.irradiance.srv.Get(), t.inscatter.srv.Get(),
                                           composition.otherModel};
    context->PSSetShaderResources(0, 6, inputs);
    context->PSSetSamplers(0, 1, linearClamp_.GetAddressOf());
    fullscreen_.draw(context, shaders, kVertexShader, pixelShader);
    ID3D11ShaderResourceView* none[6] = {};
    context->PSSetShaderResources(0, 6, none);
}

}  // namespace firmament
