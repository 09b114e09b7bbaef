#include "atmosphere/Atmosphere.h"

#include "atmosphere/SunDisc.h"
#include "atmosphere/bruneton/BrunetonTableFiles.h"
#include "atmosphere/hillaire/HillaireTableFiles.h"
#include "atmosphere/yusov/YusovTableFiles.h"
#include "gpu/CommonStates.h"
#include "tables/TimeTables.h"

#include <cmath>

namespace firmament {

namespace {
const ShaderKey kDifferenceVertexShader{"atmosphere/model_difference.hlsl", "vs_main", "vs_5_0", {}};
ShaderKey differencePixelShader(AtmospherePart part) {
    return {"atmosphere/model_difference.hlsl", part == AtmospherePart::Sky ? "ps_sky" : "ps_aerial_perspective", "ps_5_0", {}};
}

void copyTexture(ID3D11Device* device, ID3D11DeviceContext* context, const Texture2D& from, Texture2D& to) {
    if (to.width != from.width || to.height != from.height || to.format != from.format)
        to = createColorTexture(device, from.width, from.height, from.format, D3D11_BIND_SHADER_RESOURCE);
    context->CopyResource(to.texture.Get(), from.texture.Get());
}
}  // namespace

Atmosphere::Atmosphere(ID3D11Device* device, TableStorage storage)
    : device_(device),
      storage_(std::move(storage)),
      yusov_("atmosphere", "Atmosphere tables (Yusov)"),
      bruneton_("atmosphere (Bruneton 2008)", "Atmosphere tables (Bruneton)"),
      hillaire_("atmosphere (Hillaire 2020)", "Atmosphere tables (Hillaire)"),
      yusovPass_(device),
      brunetonPass_(device),
      hillairePass_(device),
      yusovConstants_(device),
      brunetonPhysics_(device),
      brunetonConstants_(device),
      hillairePhysics_(device),
      hillaireConstants_(device),
      linearClamp_(states::linearClamp(device)),
      difference_(device) {}

void Atmosphere::update(FrameContext& frame, const AtmosphereSettings& settings) {
    if (!settings.enabled) return;
    if (drawsModel(settings, AtmosphereModel::Yusov2013)) {
        const AtmosphereParameters wanted = AtmosphereParameters::from(settings);
        yusov_.update(device_, frame.context, frame.shaders, frame.profiler, storage_, yusovTableKey(wanted, frame.shaders),
                      [&] { return std::make_unique<YusovPrecomputation>(device_, wanted); }, frame.finishWorkNow);
    }
    if (drawsModel(settings, AtmosphereModel::Bruneton2008)) {
        const BrunetonParameters wanted = BrunetonParameters::from(settings);
        bruneton_.update(device_, frame.context, frame.shaders, frame.profiler, storage_, brunetonTableKey(wanted, frame.shaders),
                         [&] { return std::make_unique<BrunetonPrecomputation>(device_, wanted); }, frame.finishWorkNow);
    }
    if (drawsModel(settings, AtmosphereModel::Hillaire2020)) {
        const HillaireParameters wanted = HillaireParameters::from(settings);
        hillaire_.update(device_, frame.context, frame.shaders, frame.profiler, storage_, hillaireTableKey(wanted, frame.shaders),
                         [&] { return std::make_unique<HillairePrecomputation>(device_, wanted); }, frame.finishWorkNow);
    }
}

bool Atmosphere::ready(const AtmosphereSettings& settings) const {
    return settings.enabled && (!drawsModel(settings, AtmosphereModel::Yusov2013) || yusov_.current()) &&
           (!drawsModel(settings, AtmosphereModel::Bruneton2008) || bruneton_.current()) &&
           (!drawsModel(settings, AtmosphereModel::Hillaire2020) || hillaire_.current());
}

void Atmosphere::renderSky(FrameContext& frame, const AtmosphereSettings& settings) {
    if (ready(settings) && drawsModel(settings, AtmosphereModel::Hillaire2020)) {
        auto pass = frame.profiler.scope("Sky-view and aerial perspective (Hillaire)");
        hillairePass_.makeCameraTables(frame.context, frame.shaders, *hillaire_.current(), frame.frameConstants, HillaireFrameSampling::from(settings));
    }
    render(frame, settings, AtmospherePart::Sky);
}

void Atmosphere::renderAerialPerspective(FrameContext& frame, const AtmosphereSettings& settings) {
    render(frame, settings, AtmospherePart::AerialPerspective);
}

// The part for each region (ModelRegions.h), in order; in the difference view both models over
// the whole frame, each copied, then their difference.
void Atmosphere::render(FrameContext& frame, const AtmosphereSettings& settings, AtmospherePart part) {
    if (!ready(settings)) return;
    auto pass = frame.profiler.scope(part == AtmospherePart::Sky ? "Sky" : "Aerial perspective");
    ID3D11ShaderResourceView* scene = part == AtmospherePart::AerialPerspective ? frame.targets.copyHdr(frame.context).srv.Get() : nullptr;
    const std::vector<ModelRegion> regions = modelRegions(settings, frame.width());
    if (settings.comparison != ModelComparison::Difference) {
        for (const ModelRegion& region : regions) drawModel(frame, settings, part, region, scene);
        return;
    }
    const Texture2D& target = frame.targets.hdr();
    drawModel(frame, settings, part, regions[0], scene);
    copyTexture(device_, frame.context, target, firstModel_);
    drawModel(frame, settings, part, regions[1], scene);
    copyTexture(device_, frame.context, target, secondModel_);
    difference_.bindTarget(frame.context, target.rtv.Get(), target.width, target.height);
    difference_.draw(frame.context, frame.shaders, kDifferenceVertexShader, differencePixelShader(part), {},
                     {firstModel_.srv.Get(), frame.targets.depth().srv.Get(), secondModel_.srv.Get()}, linearClamp_.Get());
}

void Atmosphere::drawModel(FrameContext& frame, const AtmosphereSettings& settings, AtmospherePart part, const ModelRegion& region,
                           ID3D11ShaderResourceView* scene) {
    ID3D11ShaderResourceView* depth = frame.targets.depth().srv.Get();
    const Texture2D& target = frame.targets.hdr();
    switch (region.model) {
        case AtmosphereModel::Yusov2013:
            yusovPass_.render(frame.context, frame.shaders, part, settings, *yusov_.current(), frame.frameConstants, scene, depth, target, region.columns);
            break;
        case AtmosphereModel::Bruneton2008:
            brunetonPass_.render(frame.context, frame.shaders, part, *bruneton_.current(), frame.frameConstants, scene, depth, target, region.columns);
            break;
        case AtmosphereModel::Hillaire2020:
            hillairePass_.render(frame.context, frame.shaders, part, *hillaire_.current(), frame.frameConstants, scene, depth, target, region.columns);
            break;
    }
}

std::vector<GroundLighting> Atmosphere::groundLighting(FrameContext& frame, const AtmosphereSettings& settings) {
    if (!ready(settings)) return {GroundLighting{}};
    std::vector<ModelRegion> regions = modelRegions(settings, frame.width());
    if (settings.comparison == ModelComparison::Difference) regions.resize(1);  // the first model lights the ground
    std::vector<GroundLighting> lighting;
    for (const ModelRegion& region : regions) lighting.push_back(groundLightingOf(frame, region));
    return lighting;
}

GroundLighting Atmosphere::groundLightingOf(FrameContext& frame, const ModelRegion& region) {
    GroundLighting g;
    g.firstColumn = region.columns.first;
    g.endColumn = region.columns.end;
    switch (region.model) {
        case AtmosphereModel::Yusov2013:
            yusovConstants_.update(frame.context, yusov_.current()->parameters().constants());
            g.model = GroundLightingModel::Yusov2013;
            g.atmosphere = yusovConstants_.get();
            g.sunTransmittance = yusov_.current()->tables().netDensity.srv.Get();
            g.skyIrradiance = yusov_.current()->tables().ambientLight.srv.Get();
            break;
        case AtmosphereModel::Bruneton2008: {
            const BrunetonPrecomputation& b = *bruneton_.current();
            brunetonPhysics_.update(frame.context, b.parameters().physics.constants());
            brunetonConstants_.update(frame.context, b.parameters().constants());
            g.model = GroundLightingModel::Bruneton2008;
            g.atmosphere = brunetonPhysics_.get();
            g.modelConstants = brunetonConstants_.get();
            g.sunTransmittance = b.tables().transmittance.srv.Get();
            g.skyIrradiance = b.tables().irradiance.srv.Get();
            break;
        }
        case AtmosphereModel::Hillaire2020: {
            const HillairePrecomputation& h = *hillaire_.current();
            hillairePhysics_.update(frame.context, h.parameters().physics.constants());
            hillaireConstants_.update(frame.context, h.parameters().constants());
            g.model = GroundLightingModel::Hillaire2020;
            g.atmosphere = hillairePhysics_.get();
            g.modelConstants = hillaireConstants_.get();
            g.sunTransmittance = h.tables().transmittance.srv.Get();
            g.skyIrradiance = h.tables().irradiance.srv.Get();
            break;
        }
    }
    return g;
}

ScatteringLookup Atmosphere::scatteringLookup(FrameContext& frame, const AtmosphereSettings& settings) {
    ScatteringLookup l;
    const YusovPrecomputation* tables = yusov_.current();
    if (!settings.enabled || !tables) return l;
    yusovConstants_.update(frame.context, tables->parameters().constants());
    const YusovTables& t = tables->tables();
    l.ready = true;
    l.atmosphere = yusovConstants_.get();
    l.netDensity = t.netDensity.srv.Get();
    l.singleScattering = t.singleScattering.srv.Get();
    l.highOrderScattering = t.highOrderScattering.srv.Get();
    l.multipleScattering = t.multipleScattering.srv.Get();
    l.ambientLight = t.ambientLight.srv.Get();
    l.linearClamp = linearClamp_.Get();
    l.singleMode = settings.singleScattering;
    l.multipleMode = settings.multipleScattering;
    l.integrationSteps = settings.integrationSteps;
    l.sunCosAngularRadius = static_cast<float>(std::cos(kSunAngularRadius));
    l.sunDiscRadiance = static_cast<float>(sunDiscRadiance());
    return l;
}

BrunetonLookup Atmosphere::brunetonLookup(FrameContext& frame, const AtmosphereSettings& settings) {
    BrunetonLookup l;
    const BrunetonPrecomputation* tables = bruneton_.current();
    if (!settings.enabled || !tables) return l;
    brunetonPhysics_.update(frame.context, tables->parameters().physics.constants());
    brunetonConstants_.update(frame.context, tables->parameters().constants());
    l.ready = true;
    l.atmosphere = brunetonPhysics_.get();
    l.bruneton = brunetonConstants_.get();
    l.transmittance = tables->tables().transmittance.srv.Get();
    l.irradiance = tables->tables().irradiance.srv.Get();
    l.inscatter = tables->tables().inscatter.srv.Get();
    l.linearClamp = linearClamp_.Get();
    return l;
}

HillaireLookup Atmosphere::hillaireLookup(FrameContext& frame, const AtmosphereSettings& settings) {
    HillaireLookup l;
    const HillairePrecomputation* tables = hillaire_.current();
    if (!settings.enabled || !tables) return l;
    hillairePhysics_.update(frame.context, tables->parameters().physics.constants());
    hillaireConstants_.update(frame.context, HillairePass::constants(tables->parameters(), HillaireFrameSampling::from(settings)));
    l.ready = true;
    l.atmosphere = hillairePhysics_.get();
    l.hillaire = hillaireConstants_.get();
    l.transmittance = tables->tables().transmittance.srv.Get();
    l.multipleScattering = tables->tables().multipleScattering.srv.Get();
    l.irradiance = tables->tables().irradiance.srv.Get();
    l.linearClamp = linearClamp_.Get();
    return l;
}

std::vector<TableTiming> Atmosphere::timeTables(ID3D11DeviceContext* context, ShaderLibrary& shaders, const AtmosphereSettings& settings,
                                                const std::filesystem::path& scratch) {
    std::vector<TableTiming> timings;
    if (drawsModel(settings, AtmosphereModel::Yusov2013)) {
        const AtmosphereParameters p = AtmosphereParameters::from(settings);
        timings.push_back(firmament::timeTables(
            "Yusov 2013", yusovTableKey(p, shaders), [&] { return std::make_unique<YusovPrecomputation>(device_, p); }, device_, context, shaders,
            scratch));
    }
    if (drawsModel(settings, AtmosphereModel::Bruneton2008)) {
        const BrunetonParameters p = BrunetonParameters::from(settings);
        timings.push_back(firmament::timeTables(
            "Bruneton 2008", brunetonTableKey(p, shaders), [&] { return std::make_unique<BrunetonPrecomputation>(device_, p); }, device_, context,
            shaders, scratch));
    }
    if (drawsModel(settings, AtmosphereModel::Hillaire2020)) {
        const HillaireParameters p = HillaireParameters::from(settings);
        timings.push_back(firmament::timeTables(
            "Hillaire 2020", hillaireTableKey(p, shaders), [&] { return std::make_unique<HillairePrecomputation>(device_, p); }, device_, context,
            shaders, scratch));
    }
    return timings;
}

// The mean of the pending computations' progress.
std::optional<double> Atmosphere::recomputeProgress() const {
    double sum = 0.0;
    int pending = 0;
    if (const YusovPrecomputation* y = yusov_.pending()) sum += y->progress(), ++pending;
    if (const BrunetonPrecomputation* b = bruneton_.pending()) sum += b->progress(), ++pending;
    if (const HillairePrecomputation* h = hillaire_.pending()) sum += h->progress(), ++pending;
    if (pending == 0) return std::nullopt;
    return sum / pending;
}

ExrAttributes Atmosphere::captureAttributes(const AtmosphereSettings& settings) const {
    ExrAttributes a;
    if (!settings.enabled) return a;
    if (yusov_.current()) a = yusov_.current()->parameters().exrAttributes();
    else if (bruneton_.current()) a = bruneton_.current()->parameters().physics.exrAttributes();
    else if (hillaire_.current()) a = hillaire_.current()->parameters().physics.exrAttributes();
    if (bruneton_.current()) a["firmament.atmosphere.groundAlbedo"] = static_cast<float>(bruneton_.current()->parameters().groundAlbedo);
    a["firmament.atmosphere.model"] = std::string(kAtmosphereModelNames[static_cast<size_t>(settings.model)]);
    a["firmament.atmosphere.comparison"] = std::string(kModelComparisonNames[static_cast<size_t>(settings.comparison)]);
    if (settings.comparison == ModelComparison::Split || settings.comparison == ModelComparison::Difference)
        a["firmament.atmosphere.comparedModel"] = std::string(kAtmosphereModelNames[static_cast<size_t>(settings.comparedModel)]);
    return a;
}

}  // namespace firmament
