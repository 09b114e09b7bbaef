#include "atmosphere/Atmosphere.h"

#include "atmosphere/SunDisc.h"
#include "atmosphere/bruneton/BrunetonTableFiles.h"
#include "atmosphere/yusov/YusovTableFiles.h"
#include "gpu/CommonStates.h"
#include "tables/TimeTables.h"

#include <cmath>

namespace firmament {

namespace {
bool usesYusov(const AtmosphereSettings& s) { return s.model == AtmosphereModel::Yusov2013 || s.comparison != ModelComparison::None; }
bool usesBruneton(const AtmosphereSettings& s) { return s.model == AtmosphereModel::Bruneton2008 || s.comparison != ModelComparison::None; }

void copyTexture(ID3D11Device* device, ID3D11DeviceContext* context, const Texture2D& from, Texture2D& to) {
    if (to.width != from.width || to.height != from.height)
        to = createColorTexture(device, from.width, from.height, from.format, D3D11_BIND_SHADER_RESOURCE);
    context->CopyResource(to.texture.Get(), from.texture.Get());
}
}  // namespace

Atmosphere::Atmosphere(ID3D11Device* device, TableStorage storage)
    : device_(device),
      storage_(std::move(storage)),
      yusov_("atmosphere", "Atmosphere tables (Yusov)"),
      bruneton_("atmosphere (Bruneton 2008)", "Atmosphere tables (Bruneton)"),
      yusovPass_(device),
      brunetonPass_(device),
      yusovConstants_(device),
      brunetonPhysics_(device),
      brunetonConstants_(device),
      linearClamp_(states::linearClamp(device)) {}

void Atmosphere::update(FrameContext& frame, const AtmosphereSettings& settings) {
    if (!settings.enabled) return;
    if (usesYusov(settings)) {
        const AtmosphereParameters wanted = AtmosphereParameters::from(settings);
        yusov_.update(device_, frame.context, frame.shaders, frame.profiler, storage_, yusovTableKey(wanted, frame.shaders),
                      [&] { return std::make_unique<YusovPrecomputation>(device_, wanted); }, frame.finishWorkNow);
    }
    if (usesBruneton(settings)) {
        const BrunetonParameters wanted = BrunetonParameters::from(settings);
        bruneton_.update(device_, frame.context, frame.shaders, frame.profiler, storage_, brunetonTableKey(wanted, frame.shaders),
                         [&] { return std::make_unique<BrunetonPrecomputation>(device_, wanted); }, frame.finishWorkNow);
    }
}

bool Atmosphere::ready(const AtmosphereSettings& settings) const {
    return settings.enabled && (!usesYusov(settings) || yusov_.current()) && (!usesBruneton(settings) || bruneton_.current());
}

void Atmosphere::renderSky(FrameContext& frame, const AtmosphereSettings& settings) { render(frame, settings, AtmospherePart::Sky); }

void Atmosphere::renderAerialPerspective(FrameContext& frame, const AtmosphereSettings& settings) {
    render(frame, settings, AtmospherePart::AerialPerspective);
}

// The part for the models the settings draw: one of them; both side by side, Yusov's everywhere
// and Bruneton's over it from the middle column on; or Bruneton's as its difference from
// Yusov's, which is drawn first and copied.
void Atmosphere::render(FrameContext& frame, const AtmosphereSettings& settings, AtmospherePart part) {
    if (!ready(settings)) return;
    auto pass = frame.profiler.scope(part == AtmospherePart::Sky ? "Sky" : "Aerial perspective");
    ID3D11ShaderResourceView* depth = frame.targets.depth().srv.Get();
    ID3D11ShaderResourceView* scene = part == AtmospherePart::AerialPerspective ? frame.targets.copyHdr(frame.context).srv.Get() : nullptr;
    const Texture2D& target = frame.targets.hdr();
    const auto yusov = [&] {
        yusovPass_.render(frame.context, frame.shaders, part, settings, *yusov_.current(), frame.frameConstants, scene, depth, target);
    };
    const auto bruneton = [&](const BrunetonComposition& composition) {
        brunetonPass_.render(frame.context, frame.shaders, part, *bruneton_.current(), frame.frameConstants, scene, depth, target, composition);
    };
    switch (settings.comparison) {
        case ModelComparison::None:
            if (settings.model == AtmosphereModel::Yusov2013) yusov();
            else bruneton({});
            break;
        case ModelComparison::Split:
            yusov();
            bruneton({BrunetonView::RightOfColumn, static_cast<unsigned>(frame.width() / 2), nullptr});
            break;
        case ModelComparison::Difference:
            yusov();
            copyTexture(device_, frame.context, target, yusovFrame_);
            bruneton({BrunetonView::DifferenceFromOther, 0, yusovFrame_.srv.Get()});
            break;
    }
}

std::vector<GroundLighting> Atmosphere::groundLighting(FrameContext& frame, const AtmosphereSettings& settings) {
    if (!ready(settings)) return {GroundLighting{}};
    std::vector<GroundLighting> regions;
    if (usesYusov(settings)) {  // Yusov's model, or a comparison (its left side)
        yusovConstants_.update(frame.context, yusov_.current()->parameters().constants());
        GroundLighting g;
        g.model = GroundLightingModel::Yusov2013;
        g.atmosphere = yusovConstants_.get();
        g.sunTransmittance = yusov_.current()->tables().netDensity.srv.Get();
        g.skyIrradiance = yusov_.current()->tables().ambientLight.srv.Get();
        if (settings.comparison == ModelComparison::Split) g.endColumn = frame.width() / 2;
        regions.push_back(g);
    }
    if ((settings.model == AtmosphereModel::Bruneton2008 && settings.comparison == ModelComparison::None) ||
        settings.comparison == ModelComparison::Split) {
        const BrunetonPrecomputation& b = *bruneton_.current();
        brunetonPhysics_.update(frame.context, b.parameters().physics.constants());
        brunetonConstants_.update(frame.context, b.parameters().constants());
        GroundLighting g;
        g.model = GroundLightingModel::Bruneton2008;
        g.atmosphere = brunetonPhysics_.get();
        g.bruneton = brunetonConstants_.get();
        g.sunTransmittance = b.tables().transmittance.srv.Get();
        g.skyIrradiance = b.tables().irradiance.srv.Get();
        if (settings.comparison == ModelComparison::Split) g.firstColumn = frame.width() / 2;
        regions.push_back(g);
    }
    return regions;
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

std::vector<TableTiming> Atmosphere::timeTables(ID3D11DeviceContext* context, ShaderLibrary& shaders, const AtmosphereSettings& settings,
                                                const std::filesystem::path& scratch) {
    std::vector<TableTiming> timings;
    if (usesYusov(settings)) {
        const AtmosphereParameters p = AtmosphereParameters::from(settings);
        timings.push_back(firmament::timeTables(
            "Yusov 2013", yusovTableKey(p, shaders), [&] { return std::make_unique<YusovPrecomputation>(device_, p); }, device_, context, shaders,
            scratch));
    }
    if (usesBruneton(settings)) {
        const BrunetonParameters p = BrunetonParameters::from(settings);
        timings.push_back(firmament::timeTables(
            "Bruneton 2008", brunetonTableKey(p, shaders), [&] { return std::make_unique<BrunetonPrecomputation>(device_, p); }, device_, context,
            shaders, scratch));
    }
    return timings;
}

std::optional<double> Atmosphere::recomputeProgress() const {
    const YusovPrecomputation* y = yusov_.pending();
    const BrunetonPrecomputation* b = bruneton_.pending();
    if (y && b) return (y->progress() + b->progress()) * 0.5;
    if (y) return y->progress();
    if (b) return b->progress();
    return std::nullopt;
}

ExrAttributes Atmosphere::captureAttributes(const AtmosphereSettings& settings) const {
    ExrAttributes a;
    if (!settings.enabled) return a;
    if (yusov_.current()) a = yusov_.current()->parameters().exrAttributes();
    else if (bruneton_.current()) a = bruneton_.current()->parameters().physics.exrAttributes();
    if (bruneton_.current()) a["firmament.atmosphere.groundAlbedo"] = static_cast<float>(bruneton_.current()->parameters().groundAlbedo);
    a["firmament.atmosphere.model"] = std::string(kAtmosphereModelNames[static_cast<size_t>(settings.model)]);
    a["firmament.atmosphere.comparison"] = std::string(kModelComparisonNames[static_cast<size_t>(settings.comparison)]);
    return a;
}

}  // namespace firmament
