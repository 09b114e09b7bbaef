#include "lightshafts/LightShafts.h"


namespace firmament {

namespace {
const ShaderKey kVertexShader{"lightshafts/brute_force.hlsl", "vs_main", "vs_5_0", {}};
const ShaderKey kPixelShader{"lightshafts/brute_force.hlsl", "ps_main", "ps_5_0", {}};
// Steps through one cascade when the shadow maps are off (the march then has nothing to read).
constexpr int kDefaultCascadeResolution = 1024;
}  // namespace

LightShafts::LightShafts(ID3D11Device* device)
    : epipolar_(device), fullscreen_(device), constants_(device), noShadows_(device), noClouds_(device) {}

gpu::LightShaftConstants LightShafts::constants(const LightShaftSettings& settings, const ScatteringLookup& lookup, int cascadeResolution) {
    gpu::LightShaftConstants c{};
    c.mode = glm::uvec4(static_cast<unsigned>(lookup.singleMode), static_cast<unsigned>(lookup.integrationSteps),
                        static_cast<unsigned>(lookup.multipleMode), static_cast<unsigned>(settings.firstCascade));
    c.options = glm::uvec4(settings.lightingOnly ? 1u : 0u, 0u, 0u, 0u);
    // One step per texel along the cascade's longest line (its diagonal) at most.
    const int resolution = cascadeResolution > 0 ? cascadeResolution : kDefaultCascadeResolution;
    c.march = glm::vec4(kLightShaftReach, static_cast<float>(resolution) * 1.5f, settings.scatteringScale, 0.0f);
    c.sun = glm::vec4(lookup.sunCosAngularRadius, lookup.sunDiscRadiance, 0.0f, 0.0f);
    return c;
}

void LightShafts::render(FrameContext& frame, const LightShaftSettings& settings, const ScatteringLookup& lookup, const ShadowInputs& shadows,
                         const CloudShadowInputs& cloudInputs) {
    if (!lookup.ready) return;
    ID3D11DeviceContext* context = frame.context;
    constants_.update(context, constants(settings, lookup, shadows.map ? shadows.resolution : 0));
    ID3D11Buffer* shadowConstants = shadows.constants;
    if (!shadows.map) {
        noShadows_.update(context, gpu::ShadowConstants{});
        shadowConstants = noShadows_.get();
    }
    if (settings.technique != LightShaftTechnique::BruteForce) {
        epipolar_.render(frame, settings, lookup, shadows, constants_.get(), shadowConstants, cloudInputs);  // binds its own "none"
        return;
    }
    CloudShadowInputs clouds = cloudInputs;
    if (!clouds.constants || !clouds.map) {
        noClouds_.update(context, gpu::CloudShadowConstants{});
        clouds = {noClouds_.get(), nullptr};
    }
    renderBruteForce(frame, lookup, shadows, shadowConstants, clouds);
}

void LightShafts::renderBruteForce(FrameContext& frame, const ScatteringLookup& lookup, const ShadowInputs& shadows, ID3D11Buffer* shadowConstants,
                                   const CloudShadowInputs& clouds) {
    auto pass = frame.profiler.scope("Light shafts (brute force)");
    ID3D11DeviceContext* context = frame.context;
    ID3D11ShaderResourceView* scene = frame.targets.copyHdr(context).srv.Get();
    fullscreen_.bindTarget(context, frame.targets.hdr().rtv.Get(), frame.width(), frame.height());
    context->PSSetSamplers(1, 1, &shadows.comparison);
    fullscreen_.draw(context, frame.shaders, kVertexShader, kPixelShader,
                     {frame.frameConstants, lookup.atmosphere, constants_.get(), shadowConstants, clouds.constants},
                     {scene, frame.targets.depth().srv.Get(), lookup.netDensity, lookup.singleScattering, lookup.highOrderScattering,
                      lookup.multipleScattering, shadows.map, clouds.map},
                     lookup.linearClamp);
}

}  // namespace firmament
