#include "app/BenchmarkRunner.h"

#include "core/Log.h"
#include "tables/StagedComputation.h"

#include <chrono>

namespace firmament {

namespace {
constexpr double kFrameStep = 1.0 / 60.0;  // the headless runs' fixed step (light adaptation sees it)
}  // namespace

BenchmarkRun runBenchmark(Renderer& renderer, ID3D11DeviceContext* context, const BenchmarkPlan& plan, const std::filesystem::path& scratch) {
    using Clock = std::chrono::steady_clock;
    BenchmarkRun run;
    GpuProfiler& profiler = renderer.profiler();
    glm::ivec2 size{0};
    for (size_t i = 0; i < plan.scenarios.size(); ++i) {
        const BenchmarkScenario& scenario = plan.scenarios[i];
        log::info("benchmark: " + std::to_string(i + 1) + " of " + std::to_string(plan.scenarios.size()) + ": " + scenario.name);
        if (scenario.resolution != size) {
            size = scenario.resolution;
            renderer.resize(size.x, size.y, true, renderer.targets().precision());  // as --hdr-float32 made it
        }
        FrameTime time{0.0, kFrameStep};
        for (int frame = 0; frame < plan.warmupFrames; ++frame, time.seconds += kFrameStep)
            renderer.render(scenario.state, time, true, nullptr, nullptr);
        waitForGpu(context);
        profiler.reset();
        profiler.keepSamples(true);
        std::vector<double> wallMs;
        for (int frame = 0; frame < plan.measuredFrames; ++frame, time.seconds += kFrameStep) {
            const auto start = Clock::now();
            renderer.render(scenario.state, time, true, nullptr, nullptr);
            waitForGpu(context);
            wallMs.push_back(std::chrono::duration<double, std::milli>(Clock::now() - start).count());
        }
        profiler.flush();
        profiler.keepSamples(false);
        ScenarioResult result;
        result.scenario = &scenario;
        result.frameWall = timeStatistics(wallMs);
        result.disjointFrames = profiler.disjointFrames();
        for (const PassTiming& t : profiler.timings()) {
            if (t.name == "Frame") result.frameGpu = timeStatistics(t.samplesMs);
            else result.passes.push_back({t.name, timeStatistics(t.samplesMs)});
        }
        result.counts = renderer.counts(scenario.state);
        run.results.push_back(std::move(result));
    }
    // Last, so that its minute of work does not disturb the frames' measurements.
    if (plan.tables) {
        log::info("benchmark: timing the tables, computed and loaded from a cache");
        run.tables = renderer.timeTables(plan.baseState, scratch);
    }
    return run;
}

}  // namespace firmament
