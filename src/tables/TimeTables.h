#pragma once
// Times a set of tables for the benchmark (tables/TableTiming.h): computes them at once, writes
// them into a scratch folder as the cache would, and reads them back, waiting for the GPU after each.
#include "core/Error.h"
#include "tables/StagedComputation.h"
#include "tables/TableTiming.h"

#include <chrono>
#include <filesystem>
#include <memory>
#include <string>

namespace firmament {

// `make()` makes a fresh computation of the tables; readTables / writeTables are the model's
// overloads (CachedTables.h). Throws Error when the scratch folder cannot be written or read.
template <typename Make>
TableTiming timeTables(const std::string& name, const std::string& key, Make&& make, ID3D11Device* device, ID3D11DeviceContext* context,
                       ShaderLibrary& shaders, const std::filesystem::path& scratch) {
    using Clock = std::chrono::steady_clock;
    const auto seconds = [](Clock::time_point since) { return std::chrono::duration<double>(Clock::now() - since).count(); };
    TableTiming t{name, key};
    auto computed = make();
    waitForGpu(context);
    auto start = Clock::now();
    computed->runAll(context, shaders);  // waits for the GPU at its end
    t.computeSeconds = seconds(start);
    std::error_code ec;
    std::filesystem::create_directories(scratch, ec);
    writeTables(device, context, *computed, key, scratch, "timing-");
    auto loaded = make();
    waitForGpu(context);
    start = Clock::now();
    const std::string why = readTables(context, *loaded, key, scratch, "timing-");
    waitForGpu(context);
    t.cacheLoadSeconds = seconds(start);
    if (!why.empty()) throw Error("timing the tables' cache: " + why);
    return t;
}

}  // namespace firmament
