// The program's measurements (App.h): --benchmark's scenarios run, reported as a table and
// written as JSON, and the GPU time per pass printed at the end of every run.
#include "app/App.h"

#include "app/BenchmarkRunner.h"
#include "core/FileIO.h"
#include "core/Log.h"
#include "FirmamentVersion.h"

#include <cstdio>
#include <filesystem>
#include <string>
#include <system_error>

namespace firmament {

int App::runBenchmark(const BenchmarkPlan& plan) {
    ensureWritable(options_.benchmarkResults());
    log::info("benchmark '" + plan.name + "': " + std::to_string(plan.scenarios.size()) + " scenarios, " + std::to_string(plan.warmupFrames) +
              " warm-up and " + std::to_string(plan.measuredFrames) + " measured frames each, on " + gpu_->device.describe());
    const auto scratch = std::filesystem::temp_directory_path() / ("firmament-benchmark-" + std::to_string(GetCurrentProcessId()));
    const BenchmarkRun run = firmament::runBenchmark(gpu_->renderer, gpu_->device.context(), plan, scratch);
    std::error_code ec;
    std::filesystem::remove_all(scratch, ec);
    const BenchmarkInfo info{kFirmamentVersion, gpu_->device.describe(), implementationId(gpu_->device.implementation()),
                             options_.benchmark ? options_.benchmark->string() : std::string()};
    const std::string text = benchmarkReport(plan, run.results, run.tables, info).dump(2) + "\n";
    writeFileText(options_.benchmarkResults(), text);
    std::fputs(benchmarkTable(plan, run.results, run.tables).c_str(), stdout);
    std::printf("\nbenchmark results written to %s\n", options_.benchmarkResults().string().c_str());
    std::fflush(stdout);
    return 0;
}

void App::printTimings() {
    GpuProfiler& profiler = gpu_->renderer.profiler();
    profiler.flush();
    std::printf("GPU time per pass over %llu frames at %dx%d on %s:\n", static_cast<unsigned long long>(timer_.frameCount()),
                gpu_->renderer.targets().width(), gpu_->renderer.targets().height(), gpu_->device.describe().c_str());
    std::printf("  %-24s %10s %10s %10s\n", "pass", "mean ms", "min ms", "max ms");
    for (const PassTiming& t : profiler.timings())
        std::printf("  %-24s %10.3f %10.3f %10.3f\n", t.name.c_str(), t.meanMs, t.minMs, t.maxMs);
    if (deviceLosses_ > 0)
        std::printf("  (the device was lost %d time%s: these are the frames since it was last made again)\n", deviceLosses_,
                    deviceLosses_ == 1 ? "" : "s");
    if (profiler.disjointFrames())
        std::printf("  (%llu frames had unreliable timestamps and were left out)\n", static_cast<unsigned long long>(profiler.disjointFrames()));
    std::fflush(stdout);
}

}  // namespace firmament
