#pragma once
// Runs a benchmark plan through the renderer, headless: for each scenario its warm-up frames,
// then its measured frames, each waited for so that its wall-clock time is the whole frame's;
// the GPU profiler keeps every measured frame's time of every pass. With the plan's "tables",
// then times the base state's tables computed against loaded from a cache in `scratch`.
#include "app/BenchmarkPlan.h"
#include "app/BenchmarkReport.h"
#include "render/Renderer.h"

#include <filesystem>
#include <vector>

namespace firmament {

struct BenchmarkRun {
    std::vector<ScenarioResult> results;  // one per plan scenario, in its order
    std::vector<TableTiming> tables;
};

BenchmarkRun runBenchmark(Renderer& renderer, ID3D11DeviceContext* context, const BenchmarkPlan& plan, const std::filesystem::path& scratch);

}  // namespace firmament
