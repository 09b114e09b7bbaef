#include "atmosphere/bruneton/BrunetonPass.h"

#include "atmosphere/SunDisc.h"
#include "gpu/CommonStates.h"

namespace firmament {

namespace {
const std::string kShaderFile = "atmosphere/bruneton/render.hlsl";
}  // namespace

BrunetonPass::BrunetonPass(ID3D11Device* device)
    : fullscreen_(device), atmosphere_(device), bruneton_(device), constants_(device), linearClamp_(states::linearClamp(device)) {}

void BrunetonPass::render(ID3D11DeviceContext* context, ShaderLibrary& shaders, AtmospherePart part, const BrunetonPrecomputation& tables,
                          ID3D11Buffer* frameConstants, ID3D11ShaderResourceView* sceneRadiance, ID3D11ShaderResourceView* depth,
                          const Texture2D& target, Columns columns) {
    atmosphere_.update(context, tables.parameters().physics.constants());
    bruneton_.update(context, tables.parameters().constants());
    gpu::BrunetonPassConstants constants{};
    // The same sun disc as Yusov's model draws, so that the two compare.
    constants.sun = sunDiscConstants();
    constants_.update(context, constants);

    fullscreen_.bindTarget(context, target.rtv.Get(), target.width, target.height, columns);
    const BrunetonTables& t = tables.tables();
    fullscreen_.draw(context, shaders, atmosphereVertexShader(kShaderFile), atmospherePixelShader(kShaderFile, part),
                     {frameConstants, atmosphere_.get(), bruneton_.get(), constants_.get()},
                     {sceneRadiance, depth, t.transmittance.srv.Get(), t.irradiance.srv.Get(), t.inscatter.srv.Get()},
                     linearClamp_.Get());
}

}  // namespace firmament
