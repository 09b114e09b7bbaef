#include "atmosphere/Atmosphere.h"

#include "atmosphere/ScatteringTableFiles.h"
#include "atmosphere/bruneton/BrunetonTableFiles.h"
#include "core/Error.h"
#include "core/Log.h"

namespace firmament {

namespace {
constexpr const char* kCachePrefixSeparator = "-";

bool usesYusov(const AtmosphereSettings& s) { return s.model == AtmosphereModel::Yusov2013 || s.comparison != ModelComparison::None; }
bool usesBruneton(const AtmosphereSettings& s) { return s.model == AtmosphereModel::Bruneton2008 || s.comparison != ModelComparison::None; }

void copyFrame(ID3D11Device* device, ID3D11DeviceContext* context, const Texture2D& frame, Texture2D& copy) {
    if (copy.width != frame.width || copy.height != frame.height)
        copy = createColorTexture(device, frame.width, frame.height, frame.format, D3D11_BIND_SHADER_RESOURCE);
    context->CopyResource(copy.texture.Get(), frame.texture.Get());
}
}  // namespace

Atmosphere::Atmosphere(ID3D11Device* device, TableStorage storage)
    : device_(device), storage_(std::move(storage)), pass_(device), brunetonPass_(device), groundAtmosphere_(device), groundBruneton_(device) {}

// Starts new tables when the key changed (loading them from the cache when it holds them),
// advances them by one unit (or all), and when complete caches, exports and uses them.
template <typename Precomputation, typename Parameters>
void Atmosphere::update(ModelTables<Precomputation>& m, const char* model, const char* passName, ID3D11DeviceContext* context, ShaderLibrary& shaders,
                        GpuProfiler& profiler, const Parameters& wanted, const std::string& key, bool finishNow) {
    const std::string& newest = m.pending ? m.pendingKey : m.currentKey;
    if (newest != key) {
        if (m.current) log::info(std::string(model) + ": parameters or pre-computation shaders changed: new tables " + key);
        m.pending = std::make_unique<Precomputation>(device_, wanted);
        m.pendingKey = key;
        m.pendingFromCache = false;
        if (storage_.cacheFolder) {
            const std::string why = readScatteringTables(context, *m.pending, key, *storage_.cacheFolder, key + kCachePrefixSeparator);
            if (why.empty()) {
                m.pendingFromCache = true;
                log::info(std::string(model) + ": tables " + key + " loaded from the cache in " + storage_.cacheFolder->string());
            } else if (why != "missing") {
                log::warning(std::string(model) + ": the cached tables cannot be used (" + why + "); computing them again");
            }
        }
    }
    if (!m.pending) return;
    if (!m.pending->done()) {
        auto pass = profiler.scope(passName);
        if (finishNow) m.pending->runAll(context, shaders);
        else m.pending->step(context, shaders);
    }
    if (!m.pending->done()) return;
    if (storage_.cacheFolder && !m.pendingFromCache) {
        try {
            writeScatteringTables(device_, context, *m.pending, m.pendingKey, *storage_.cacheFolder, m.pendingKey + kCachePrefixSeparator);
            log::info(std::string(model) + ": tables " + m.pendingKey + " saved to the cache in " + storage_.cacheFolder->string());
        } catch (const Error& e) {
            log::warning(std::string(model) + ": the tables were not cached: " + e.what());
        }
    }
    if (storage_.exportFolder) {
        writeScatteringTables(device_, context, *m.pending, m.pendingKey, *storage_.exportFolder, "");  // throws: the run fails
        log::info(std::string(model) + ": tables exported to " + storage_.exportFolder->string());
    }
    m.current = std::move(m.pending);
    m.currentKey = m.pendingKey;
}

void Atmosphere::update(ID3D11DeviceContext* context, ShaderLibrary& shaders, GpuProfiler& profiler, const AtmosphereSettings& settings,
                        bool finishNow) {
    if (usesYusov(settings)) {
        const AtmosphereParameters wanted = AtmosphereParameters::from(settings);
        update(yusov_, "atmosphere", "Atmosphere tables (Yusov)", context, shaders, profiler, wanted, scatteringTableKey(wanted, shaders), finishNow);
    }
    if (usesBruneton(settings)) {
        const BrunetonParameters wanted = BrunetonParameters::from(settings);
        update(bruneton_, "atmosphere (Bruneton 2008)", "Atmosphere tables (Bruneton)", context, shaders, profiler, wanted, brunetonTableKey(wanted, shaders), finishNow);
    }
}

bool Atmosphere::ready(const AtmosphereSettings& settings) const {
    return (!usesYusov(settings) || yusov_.current) && (!usesBruneton(settings) || bruneton_.current);
}

void Atmosphere::render(ID3D11DeviceContext* context, ShaderLibrary& shaders, const AtmosphereSettings& settings,
                        ID3D11Buffer* frameConstants, const Texture2D& hdrFrame, ID3D11ShaderResourceView* depth) {
    if (!ready(settings)) return;
    copyFrame(device_, context, hdrFrame, sceneCopy_);
    ID3D11ShaderResourceView* scene = sceneCopy_.srv.Get();
    const auto yusov = [&] {
        pass_.render(context, shaders, settings, yusov_.current->parameters(), yusov_.current->tables(), frameConstants, scene, depth, hdrFrame);
    };
    const auto bruneton = [&](BrunetonView view, unsigned column, ID3D11ShaderResourceView* other) {
        brunetonPass_.render(context, shaders, *bruneton_.current, frameConstants, scene, depth, hdrFrame, view, column, other);
    };
    switch (settings.comparison) {
        case ModelComparison::None:
            if (settings.model == AtmosphereModel::Yusov2013) yusov();
            else bruneton(BrunetonView::WholeFrame, 0, nullptr);
            break;
        case ModelComparison::Split:  // Yusov's on the left, Bruneton's from the middle column on
            yusov();
            bruneton(BrunetonView::RightOfColumn, static_cast<unsigned>(hdrFrame.width / 2), nullptr);
            break;
        case ModelComparison::Difference:
            yusov();
            copyFrame(device_, context, hdrFrame, otherCopy_);
            bruneton(BrunetonView::DifferenceFromOther, 0, otherCopy_.srv.Get());
            break;
    }
}

GroundLighting Atmosphere::groundLighting(ID3D11DeviceContext* context, const AtmosphereSettings& settings) {
    GroundLighting g;
    if (!settings.enabled || !ready(settings)) return g;
    if (usesYusov(settings)) {  // Yusov's model, or a comparison (its left side)
        groundAtmosphere_.update(context, yusov_.current->parameters().constants());
        g.model = GroundLightingModel::Yusov2013;
        g.sunTransmittance = yusov_.current->tables().netDensity.srv.Get();
        g.skyIrradiance = yusov_.current->tables().ambientLight.srv.Get();
        if (settings.comparison == ModelComparison::Split) {  // both models read the same physical constants
            groundBruneton_.update(context, bruneton_.current->parameters().constants());
            g.model = GroundLightingModel::Split;
            g.bruneton = groundBruneton_.get();
            g.brunetonTransmittance = bruneton_.current->tables().transmittance.srv.Get();
            g.brunetonIrradiance = bruneton_.current->tables().irradiance.srv.Get();
        }
    } else {
        groundAtmosphere_.update(context, bruneton_.current->parameters().physics.constants());
        groundBruneton_.update(context, bruneton_.current->parameters().constants());
        g.model = GroundLightingModel::Bruneton2008;
        g.bruneton = groundBruneton_.get();
        g.sunTransmittance = bruneton_.current->tables().transmittance.srv.Get();
        g.skyIrradiance = bruneton_.current->tables().irradiance.srv.Get();
    }
    g.atmosphere = groundAtmosphere_.get();
    return g;
}

std::optional<double> Atmosphere::recomputeProgress() const {
    const auto& y = yusov_.pending;
    const auto& b = bruneton_.pending;
    if (y && b) return (y->progress() + b->progress()) * 0.5;
    if (y) return y->progress();
    if (b) return b->progress();
    return std::nullopt;
}

ExrAttributes Atmosphere::captureAttributes(const AtmosphereSettings& settings) const {
    ExrAttributes a;
    if (yusov_.current) a = yusov_.current->parameters().exrAttributes();
    else if (bruneton_.current) a = bruneton_.current->parameters().physics.exrAttributes();
    if (bruneton_.current) a["firmament.atmosphere.groundAlbedo"] = static_cast<float>(bruneton_.current->parameters().groundAlbedo);
    a["firmament.atmosphere.model"] = std::string(kAtmosphereModelNames[static_cast<size_t>(settings.model)]);
    a["firmament.atmosphere.comparison"] = std::string(kModelComparisonNames[static_cast<size_t>(settings.comparison)]);
    return a;
}

}  // namespace firmament
