#pragma once
// The atmosphere technique: keeps the look-up tables for the current physical parameters and
// draws the sky, the sun and aerial perspective with them. When a setting that changes the
// tables changes, new tables are computed one unit of work per frame while the old ones stay
// in use, and replace them when complete; a headless run computes them at once. Until the
// first tables exist, ready() is false and the program shows the orientation grid's sky.
// Tables are cached on disk as OpenEXR (ScatteringTableFiles), keyed by everything that shapes
// them, and loaded instead of computed when a valid file is there.
#include "atmosphere/ScatteringPass.h"
#include "atmosphere/ScatteringPrecomputation.h"
#include "core/ExrImage.h"
#include "gpu/GpuProfiler.h"

#include <filesystem>
#include <memory>
#include <optional>

namespace firmament {

struct TableStorage {
    std::optional<std::filesystem::path> cacheFolder;   // none: no cache
    std::optional<std::filesystem::path> exportFolder;  // --export-luts: every new table set is written here
};

class Atmosphere {
public:
    Atmosphere(ID3D11Device* device, TableStorage storage);

    // Starts a recompute when the parameters changed; advances it by one unit, or finishes it
    // when `finishNow` (headless runs, and the first frame).
    // Work is timed as the pass "Atmosphere tables".
    void update(ID3D11DeviceContext* context, ShaderLibrary& shaders, GpuProfiler& profiler, const AtmosphereSettings& settings,
                bool finishNow);
    void render(ID3D11DeviceContext* context, ShaderLibrary& shaders, const AtmosphereSettings& settings, ID3D11Buffer* frameConstants,
                const Texture2D& hdrFrame, ID3D11ShaderResourceView* depth);

    bool ready() const { return current_ != nullptr; }
    // 0..1 while a recompute runs, nullopt otherwise.
    std::optional<double> recomputeProgress() const;
    // "firmament.atmosphere.*": the physical constants of the tables in use.
    ExrAttributes captureAttributes() const;

private:
    void start(ID3D11DeviceContext* context, const AtmosphereParameters& parameters, const std::string& key);
    void finish(ID3D11DeviceContext* context);

    ID3D11Device* device_;
    TableStorage storage_;
    ScatteringPass pass_;
    std::unique_ptr<ScatteringPrecomputation> current_;  // complete
    std::unique_ptr<ScatteringPrecomputation> pending_;  // being computed
    std::string currentKey_, pendingKey_;
    bool pendingFromCache_ = false;
};

}  // namespace firmament
