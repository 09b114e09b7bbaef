#pragma once
// The atmosphere technique: keeps the look-up tables for the current physical parameters and
// draws the sky, the sun and aerial perspective with them. When a setting that changes the
// tables changes, new tables are computed one unit of work per frame while the old ones stay
// in use, and replace them when complete; a headless run computes them at once. Until the
// first tables exist, ready() is false and the program shows the orientation grid's sky.
#include "atmosphere/ScatteringPass.h"
#include "atmosphere/ScatteringPrecomputation.h"
#include "core/ExrImage.h"
#include "gpu/GpuProfiler.h"

#include <memory>
#include <optional>

namespace firmament {

class Atmosphere {
public:
    explicit Atmosphere(ID3D11Device* device);

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
    ID3D11Device* device_;
    ScatteringPass pass_;
    std::unique_ptr<ScatteringPrecomputation> current_;  // complete
    std::unique_ptr<ScatteringPrecomputation> pending_;  // being computed
};

}  // namespace firmament
