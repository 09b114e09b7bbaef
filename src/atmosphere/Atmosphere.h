#pragma once
// The atmosphere technique: keeps the look-up tables for the current physical parameters and
// draws the sky, the sun and aerial perspective with them, by Yusov's model (document 000) or
// Bruneton and Neyret's (document 002), or both side by side or as their difference. When a setting that changes the
// tables changes, new tables are computed one unit of work per frame while the old ones stay
// in use, and replace them when complete; a headless run computes them at once. Until the
// first tables exist, ready() is false and the program shows the orientation grid's sky.
// Both models' tables are cached on disk as OpenEXR (ScatteringTableFiles, BrunetonTableFiles),
// keyed by everything that shapes them, and loaded instead of computed when a valid file is there.
#include "atmosphere/GroundLighting.h"
#include "atmosphere/ScatteringPass.h"
#include "atmosphere/ScatteringPrecomputation.h"
#include "atmosphere/bruneton/BrunetonPass.h"
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
    // Work is timed as the passes "Atmosphere tables (Yusov)" and "Atmosphere tables (Bruneton)".
    void update(ID3D11DeviceContext* context, ShaderLibrary& shaders, GpuProfiler& profiler, const AtmosphereSettings& settings,
                bool finishNow);
    void render(ID3D11DeviceContext* context, ShaderLibrary& shaders, const AtmosphereSettings& settings, ID3D11Buffer* frameConstants,
                const Texture2D& hdrFrame, ID3D11ShaderResourceView* depth);

    // The tables that light the ground (terrain) for the model drawn: both in the split view,
    // Yusov's in the difference view; GroundLightingModel::None when scattering is off or the
    // tables are not ready.
    GroundLighting groundLighting(ID3D11DeviceContext* context, const AtmosphereSettings& settings);

    // The tables the settings' model (or both, to compare) need exist.
    bool ready(const AtmosphereSettings& settings) const;
    // 0..1 while a recompute runs, nullopt otherwise.
    std::optional<double> recomputeProgress() const;
    // "firmament.atmosphere.*": the physical constants of the tables in use, the model drawn.
    ExrAttributes captureAttributes(const AtmosphereSettings& settings) const;

private:
    // One model's tables: those in use, and those being computed.
    template <typename Precomputation>
    struct ModelTables {
        std::unique_ptr<Precomputation> current, pending;
        std::string currentKey, pendingKey;
        bool pendingFromCache = false;
    };
    template <typename Precomputation, typename Parameters>
    void update(ModelTables<Precomputation>& tables, const char* model, const char* passName, ID3D11DeviceContext* context, ShaderLibrary& shaders,
                GpuProfiler& profiler, const Parameters& wanted, const std::string& key, bool finishNow);

    ID3D11Device* device_;
    TableStorage storage_;
    ScatteringPass pass_;
    BrunetonPass brunetonPass_;
    ModelTables<ScatteringPrecomputation> yusov_;
    ModelTables<BrunetonPrecomputation> bruneton_;
    ConstantBuffer<gpu::AtmosphereConstants> groundAtmosphere_;  // the ground's copies of the models' constants
    ConstantBuffer<gpu::BrunetonConstants> groundBruneton_;
    Texture2D sceneCopy_;  // the frame before the atmosphere, which the passes read
    Texture2D otherCopy_;  // the difference view: Yusov's frame
};

}  // namespace firmament
