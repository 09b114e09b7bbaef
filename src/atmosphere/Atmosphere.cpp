#include "atmosphere/Atmosphere.h"

#include "atmosphere/ScatteringTableFiles.h"
#include "core/Error.h"
#include "core/Log.h"

namespace firmament {

namespace {
constexpr const char* kCachePrefixSeparator = "-";
}

Atmosphere::Atmosphere(ID3D11Device* device, TableStorage storage) : device_(device), storage_(std::move(storage)), pass_(device) {}

void Atmosphere::start(ID3D11DeviceContext* context, const AtmosphereParameters& parameters, const std::string& key) {
    pending_ = std::make_unique<ScatteringPrecomputation>(device_, parameters);
    pendingKey_ = key;
    pendingFromCache_ = false;
    if (!storage_.cacheFolder) return;
    const std::string why = readScatteringTables(context, *pending_, key, *storage_.cacheFolder, key + kCachePrefixSeparator);
    if (why.empty()) {
        pendingFromCache_ = true;
        log::info("atmosphere: tables " + key + " loaded from the cache in " + storage_.cacheFolder->string());
    } else if (why != "missing") {
        log::warning("atmosphere: the cached tables cannot be used (" + why + "); computing them again");
    }
}

// The pending tables are complete: cache them (if computed), export them, use them.
void Atmosphere::finish(ID3D11DeviceContext* context) {
    if (storage_.cacheFolder && !pendingFromCache_) {
        try {
            writeScatteringTables(device_, context, *pending_, pendingKey_, *storage_.cacheFolder, pendingKey_ + kCachePrefixSeparator);
            log::info("atmosphere: tables " + pendingKey_ + " saved to the cache in " + storage_.cacheFolder->string());
        } catch (const Error& e) {
            log::warning(std::string("atmosphere: the tables were not cached: ") + e.what());
        }
    }
    if (storage_.exportFolder) {
        writeScatteringTables(device_, context, *pending_, pendingKey_, *storage_.exportFolder, "");  // throws: the run fails
        log::info("atmosphere: tables exported to " + storage_.exportFolder->string());
    }
    current_ = std::move(pending_);
    currentKey_ = pendingKey_;
}

void Atmosphere::update(ID3D11DeviceContext* context, ShaderLibrary& shaders, GpuProfiler& profiler, const AtmosphereSettings& settings,
                        bool finishNow) {
    const AtmosphereParameters wanted = AtmosphereParameters::from(settings);
    const std::string key = scatteringTableKey(wanted, shaders);  // cheap: a hash of text and two shaders
    const std::string& newest = pending_ ? pendingKey_ : currentKey_;
    if (newest != key) {
        if (current_) log::info("atmosphere: parameters or pre-computation shaders changed: new tables " + key);
        start(context, wanted, key);
    }
    if (!pending_) return;
    if (!pending_->done()) {
        auto pass = profiler.scope("Atmosphere tables");
        if (finishNow) pending_->runAll(context, shaders);
        else pending_->step(context, shaders);
    }
    if (pending_->done()) finish(context);
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
    return current_->parameters().exrAttributes();
}

}  // namespace firmament
