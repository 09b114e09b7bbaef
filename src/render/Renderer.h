#pragma once
// The frame's one owner: the frame targets, the frame constants, the GPU profiler and every
// technique, called in the frame order that Renderer::render() lists, top to bottom
// (README, "Architecture"). The application drives it once a frame with the state to draw; the
// techniques stay behind this header, so that adding one touches its own folder, its settings,
// its panel file, and one line of the frame order.
#include "core/Camera.h"
#include "core/ExrImage.h"
#include "frame/FrameTargets.h"
#include "gpu/ConstantBuffer.h"
#include "gpu/GpuProfiler.h"
#include "gpu/SharedStructures.h"
#include "postfx/ExposureReading.h"
#include "tables/CachedTables.h"
#include "tables/TableTiming.h"

#include <d3d11.h>

#include <functional>
#include <memory>
#include <optional>
#include <string>

namespace firmament {

class ShaderLibrary;
struct State;
struct FrameContext;
class Atmosphere;
class CascadedShadowMaps;
class Clouds;
class LightShafts;
class OrientationGridPass;
class Terrain;
class ToneMapping;

// When the frame is: the time since the start, and the step from the last frame.
struct FrameTime {
    double seconds = 0.0;
    double deltaSeconds = 0.0;
};

// What the GUI shows of the techniques' state.
struct RendererStatus {
    ExposureReading exposure;                  // what the tone mapping applied, a few frames ago
    std::optional<double> atmosphereProgress;  // 0..1 while the atmosphere's tables are computed
    std::optional<double> cloudTableProgress;  // 0..1 while the cloud particle's tables are computed
    std::string cloudBlending;                 // how the clouds' particles are blended, and what did not fit
};

class Renderer {
public:
    // Makes every technique: the terrain's height field comes from the table cache or is
    // generated into it. Throws Error.
    Renderer(ID3D11Device* device, ID3D11DeviceContext* context, ShaderLibrary& shaders, const TableStorage& tables);
    ~Renderer();
    Renderer(const Renderer&) = delete;
    Renderer& operator=(const Renderer&) = delete;

    // (Re)creates the frame targets; `ownOutput`: an 8-bit output target of the renderer's own
    // (headless runs; a window renders into its swap chain's back buffer); `precision`: the HDR
    // radiance's floats (--hdr-float32).
    void resize(int width, int height, bool ownOutput, HdrPrecision precision = HdrPrecision::Half);

    // As a fresh start would find it, for a batch of captures (--batch): every technique that
    // keeps something from one frame to the next is made again (the exposure's adaptation and
    // its delayed read-back, the clouds' grown pools, sort order and loaded tables, the
    // cascades, the light shafts' targets). Kept: the profiler's statistics, the atmosphere's
    // tables and the terrain's height field, which depend only on their parameters (each frame
    // checks them, and loads or computes what a new process would load from the cache).
    void startOver();

    // One frame of `state` into `output` (the renderer's own when null), every pass in frame
    // order; `drawGui`, when given, is the last pass. `finishWorkNow`: work that is spread over
    // frames (the tables) completes in this one.
    void render(const State& state, FrameTime time, bool finishWorkNow, ID3D11RenderTargetView* output,
                const std::function<void(ID3D11RenderTargetView*)>& drawGui);

    // The camera a frame of `state` is drawn from: state.camera with its near plane fitted below
    // the highest surface drawn, the terrain's peaks and the clouds' layer (withFittedNearPlane).
    // Captures record its projection.
    Camera viewCamera(const State& state);
    // World y of the terrain's surface at (x, z), for the camera's clearance (the height field
    // is loaded, or generated, on the first call that needs it).
    double groundY(double x, double z);
    RendererStatus status(const State& state);
    // What each technique records of itself in a capture's header ("firmament.toneMapping.*",
    // "firmament.atmosphere.*"); waits for the GPU.
    ExrAttributes captureAttributes(const State& state);

    // What the techniques counted in the last frame of `state` (the cloud particles and valid
    // cells), for the benchmark; waits for the GPU.
    std::vector<std::pair<std::string, double>> counts(const State& state);
    // How long the tables of `state` take to compute, and to load from a cache written into
    // `scratch` (the benchmark's record).
    std::vector<TableTiming> timeTables(const State& state, const std::filesystem::path& scratch);

    const FrameTargets& targets() const { return targets_; }
    GpuProfiler& profiler() { return profiler_; }

private:
    gpu::FrameConstants frameConstants(const State& state, const Camera& camera, FrameTime time) const;
    void renderShadowsAndTerrain(FrameContext& frame, const State& state);
    void drawCloudsIntoCascades(FrameContext& frame);
    // The terrain, made from the height field the first time it is needed: a run with the
    // terrain off never reads the 16 MiB field.
    Terrain& terrain();
    bool lightShaftsDrawn(const State& state) const;

    ID3D11Device* device_;
    ID3D11DeviceContext* context_;
    ShaderLibrary& shaders_;
    TableStorage tables_;  // where the techniques' tables are cached (startOver makes the clouds again)
    GpuProfiler profiler_;
    FrameTargets targets_;
    ConstantBuffer<gpu::FrameConstants> frameConstants_;
    std::unique_ptr<OrientationGridPass> orientationGrid_;
    std::unique_ptr<Atmosphere> atmosphere_;
    std::unique_ptr<Terrain> terrain_;  // made by terrain()
    std::unique_ptr<CascadedShadowMaps> shadows_;
    std::unique_ptr<LightShafts> lightShafts_;
    std::unique_ptr<Clouds> clouds_;
    std::unique_ptr<ToneMapping> toneMapping_;
};

}  // namespace firmament
