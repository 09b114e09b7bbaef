#include "atmosphere/Atmosphere.h"

#include "core/Log.h"

namespace firmament {

Atmosphere::Atmosphere(ID3D11Device* device) : device_(device), pass_(device) {}

void Atmosphere::update(ID3D11DeviceContext* context, ShaderLibrary& shaders, GpuProfiler& profiler, const AtmosphereSettings& settings,
                        bool finishNow) {
    const AtmosphereParameters wanted = AtmosphereParameters::from(settings);
    const std::string key = wanted.describe();
    const ScatteringPrecomputation* newest = pending_ ? pending_.get() : current_.get();
    if (!newest || newest->parameters().describe() != key) {
        if (current_) log::info("atmosphere: parameters changed, recomputing the tables");
        pending_ = std::make_unique<ScatteringPrecomputation>(device_, wanted);
    }
    if (!pending_) return;
    auto pass = profiler.scope("Atmosphere tables");
    if (finishNow) {
        pending_->runAll(context, shaders);
    } else {
        pending_->step(context, shaders);
        if (pending_->done()) log::info("atmosphere: new tables in use");
    }
    if (pending_->done()) current_ = std::move(pending_);
}

void Atmosphere::render(ID3D11DeviceContext* context, ShaderLibrary& shaders, const AtmosphereSettings& settings,
                        ID3D11Buffer* frameConstants, const Texture2D& hdrFrame, ID3D11ShaderResourceView* depth) {
    if (!current_) return;
    pass_.render(context, shaders, settings, current_->parameters(), current_->tables(), frameConstants, hdrFrame, depth);
}

std::optional<double> Atmosphere::recomputeProgress() const {
    if (!pending_) return std::nullopt;
    return pending_->progress();
}

ExrAttributes Atmosphere::captureAttributes() const {
    if (!current_) return {};
    const AtmosphereParameters& p = current_->parameters();
    return {
        {"firmament.atmosphere.parameters", p.describe()},
        {"firmament.atmosphere.earthRadius", static_cast<float>(p.earthRadius)},
        {"firmament.atmosphere.atmosphereHeight", static_cast<float>(p.atmosphereHeight)},
        {"firmament.atmosphere.rayleighScattering", glm::vec3(p.rayleighScattering)},
        {"firmament.atmosphere.mieScattering", glm::vec3(p.mieScattering)},
        {"firmament.atmosphere.mieExtinction", glm::vec3(p.mieExtinction)},
        {"firmament.atmosphere.mieAsymmetry", static_cast<float>(p.mieAsymmetry)},
        {"firmament.atmosphere.scaleHeights", glm::vec3(static_cast<float>(p.rayleighScaleHeight), static_cast<float>(p.mieScaleHeight), 0.0f)},
        {"firmament.atmosphere.ozoneAbsorption", glm::vec3(p.ozoneAbsorption)},
    };
}

}  // namespace firmament
