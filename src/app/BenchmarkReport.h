#pragma once
// What a benchmark measured, as JSON (--benchmark-output) and as a table on the standard
// output: per scenario every pass's GPU time (median, min, max over the measured frames), the
// frame's GPU time and its wall-clock time, the resolution and the whole state; the ratios the
// scenario file asks for; the tables' computing and cache-loading times; the adapter and the
// version. Times are what the device's timestamps say: under Wine's WARP they time the CPU.
#include "app/BenchmarkPlan.h"
#include "tables/TableTiming.h"

#include <nlohmann/json.hpp>

#include <string>
#include <vector>

namespace firmament {

struct TimeStatistics {
    double medianMs = 0.0;
    double minMs = 0.0;
    double maxMs = 0.0;
};
// The median of an even count is the mean of the two middle samples. Empty: all zero.
TimeStatistics timeStatistics(std::vector<double> samplesMs);

struct PassResult {
    std::string name;
    TimeStatistics time;
};

struct ScenarioResult {
    const BenchmarkScenario* scenario = nullptr;
    TimeStatistics frameGpu;           // the profiler's "Frame": first timestamp to last
    TimeStatistics frameWall;          // CPU clock from the frame's start until the GPU finished it
    std::vector<PassResult> passes;    // in frame order
    unsigned long long disjointFrames = 0;  // frames whose timestamps were unreliable, left out
    std::vector<std::pair<std::string, double>> counts;  // what the techniques counted in the last frame (cloud particles, ...)
};

struct BenchmarkInfo {
    std::string version;
    std::string adapter;
    std::string implementation;  // implementationId: "wined3d", "dxvk", "windows"
    std::string scenarioFile;
};

// One ratio for one view and resolution.
struct RatioResult {
    const BenchmarkRatio* ratio = nullptr;
    std::string view;
    glm::ivec2 resolution{0};
    double frame = 0.0;   // median GPU frame time, numerator over denominator
    double passes = 0.0;  // the named passes' medians summed, numerator over denominator (0 without passes)
};
std::vector<RatioResult> benchmarkRatios(const BenchmarkPlan& plan, const std::vector<ScenarioResult>& results);

nlohmann::json benchmarkReport(const BenchmarkPlan& plan, const std::vector<ScenarioResult>& results, const std::vector<TableTiming>& tables,
                               const BenchmarkInfo& info);
std::string benchmarkTable(const BenchmarkPlan& plan, const std::vector<ScenarioResult>& results, const std::vector<TableTiming>& tables);

}  // namespace firmament
