#include "app/BenchmarkReport.h"

#include "core/SettingsJson.h"

#include <algorithm>
#include <cstdio>

namespace firmament {

using nlohmann::json;

namespace {

json statisticsJson(const TimeStatistics& t) { return {{"medianMs", t.medianMs}, {"minMs", t.minMs}, {"maxMs", t.maxMs}}; }

const PassResult* findPass(const ScenarioResult& r, const std::string& name) {
    const auto found = std::find_if(r.passes.begin(), r.passes.end(), [&](const PassResult& p) { return p.name == name; });
    return found == r.passes.end() ? nullptr : &*found;
}

const ScenarioResult* findResult(const std::vector<ScenarioResult>& results, const std::string& view, const std::string& variant, glm::ivec2 resolution) {
    for (const ScenarioResult& r : results)
        if (r.scenario->view == view && r.scenario->variant == variant && r.scenario->resolution == resolution) return &r;
    return nullptr;
}

double passSum(const ScenarioResult& r, const std::vector<std::string>& passes) {
    double sum = 0.0;
    for (const std::string& name : passes)
        if (const PassResult* p = findPass(r, name)) sum += p->time.medianMs;
    return sum;
}

std::string format(const char* pattern, double value) {
    char text[64];
    std::snprintf(text, sizeof(text), pattern, value);
    return text;
}

}  // namespace

TimeStatistics timeStatistics(std::vector<double> samples) {
    if (samples.empty()) return {};
    std::sort(samples.begin(), samples.end());
    const size_t n = samples.size();
    const double median = n % 2 ? samples[n / 2] : 0.5 * (samples[n / 2 - 1] + samples[n / 2]);
    return {median, samples.front(), samples.back()};
}

std::vector<RatioResult> benchmarkRatios(const BenchmarkPlan& plan, const std::vector<ScenarioResult>& results) {
    std::vector<RatioResult> out;
    for (const BenchmarkRatio& ratio : plan.ratios)
        for (const glm::ivec2 resolution : plan.resolutions)
            for (const BenchmarkFragment& view : plan.views) {
                const ScenarioResult* top = findResult(results, view.name, ratio.numerator, resolution);
                const ScenarioResult* bottom = findResult(results, view.name, ratio.denominator, resolution);
                if (!top || !bottom) continue;
                RatioResult r{&ratio, view.name, resolution, 0.0, 0.0};
                if (bottom->frameGpu.medianMs > 0.0) r.frame = top->frameGpu.medianMs / bottom->frameGpu.medianMs;
                if (!ratio.passes.empty() && passSum(*bottom, ratio.passes) > 0.0) r.passes = passSum(*top, ratio.passes) / passSum(*bottom, ratio.passes);
                out.push_back(r);
            }
    return out;
}

json benchmarkReport(const BenchmarkPlan& plan, const std::vector<ScenarioResult>& results, const std::vector<TableTiming>& tables,
                     const BenchmarkInfo& info) {
    json report;
    report["firmament"] = {{"version", info.version}, {"adapter", info.adapter}, {"implementation", info.implementation}};
    report["benchmark"] = {{"name", plan.name},
                           {"description", plan.description},
                           {"file", info.scenarioFile},
                           {"warmupFrames", plan.warmupFrames},
                           {"measuredFrames", plan.measuredFrames}};
    report["note"] = "GPU times come from timestamp queries around each pass. Under Wine, WARP is Wine's Direct3D 11 on llvmpipe: "
                     "its timestamps measure the CPU, not a GPU.";
    json scenarios = json::array();
    for (const ScenarioResult& r : results) {
        State state = r.scenario->state;
        json passes = json::array();
        for (const PassResult& p : r.passes) passes.push_back({{"name", p.name}, {"gpu", statisticsJson(p.time)}});
        json counts = json::object();
        for (const auto& [name, value] : r.counts) counts[name] = value;
        scenarios.push_back({{"name", r.scenario->name},
                             {"view", r.scenario->view},
                             {"variant", r.scenario->variant},
                             {"resolution", {r.scenario->resolution.x, r.scenario->resolution.y}},
                             {"frame", {{"gpu", statisticsJson(r.frameGpu)}, {"wall", statisticsJson(r.frameWall)}}},
                             {"passes", passes},
                             {"disjointFrames", r.disjointFrames},
                             {"counts", counts},
                             {"settings", stateToJson(state)}});
    }
    report["scenarios"] = scenarios;
    json ratios = json::array();
    for (const RatioResult& r : benchmarkRatios(plan, results)) {
        json entry = {{"name", r.ratio->name},
                      {"numerator", r.ratio->numerator},
                      {"denominator", r.ratio->denominator},
                      {"view", r.view},
                      {"resolution", {r.resolution.x, r.resolution.y}},
                      {"frame", r.frame}};
        if (!r.ratio->passes.empty()) entry["passes"] = {{"names", r.ratio->passes}, {"ratio", r.passes}};
        if (r.ratio->paper) entry["paper"] = *r.ratio->paper;
        ratios.push_back(entry);
    }
    report["ratios"] = ratios;
    json tableTimes = json::array();
    for (const TableTiming& t : tables)
        tableTimes.push_back({{"tables", t.name}, {"key", t.key}, {"computeSeconds", t.computeSeconds}, {"cacheLoadSeconds", t.cacheLoadSeconds}});
    report["tables"] = tableTimes;
    return report;
}

std::string benchmarkTable(const BenchmarkPlan& plan, const std::vector<ScenarioResult>& results, const std::vector<TableTiming>& tables) {
    std::string out;
    // Columns: the frame, then every pass any scenario timed, in first-seen order.
    std::vector<std::string> passes;
    for (const ScenarioResult& r : results)
        for (const PassResult& p : r.passes)
            if (std::find(passes.begin(), passes.end(), p.name) == passes.end()) passes.push_back(p.name);
    out += "Median GPU time per pass, ms, over " + std::to_string(plan.measuredFrames) + " frames after " + std::to_string(plan.warmupFrames) +
           " warm-up frames:\n";
    for (const ScenarioResult& r : results) {
        out += "\n  " + r.scenario->name + "\n";
        out += "    " + std::string("frame (GPU)") + std::string(30 - 11, ' ') + format("%10.3f", r.frameGpu.medianMs) + "   (min " +
               format("%.3f", r.frameGpu.minMs) + ", max " + format("%.3f", r.frameGpu.maxMs) + ")\n";
        out += "    " + std::string("frame (wall clock)") + std::string(30 - 18, ' ') + format("%10.3f", r.frameWall.medianMs) + "\n";
        for (const std::string& name : passes)
            if (const PassResult* p = findPass(r, name); p && name != "Frame")
                out += "    " + name + std::string(name.size() < 30 ? 30 - name.size() : 1, ' ') + format("%10.3f", p->time.medianMs) + "\n";
        for (const auto& [name, value] : r.counts)
            out += "    " + name + std::string(name.size() < 30 ? 30 - name.size() : 1, ' ') + format("%10.0f", value) + "\n";
    }
    const std::vector<RatioResult> ratios = benchmarkRatios(plan, results);
    if (!ratios.empty()) out += "\nRatios (numerator / denominator, medians):\n";
    for (const RatioResult& r : ratios) {
        out += "  " + r.ratio->name + ", " + r.view + ", " + std::to_string(r.resolution.x) + "x" + std::to_string(r.resolution.y) + ": frame " +
               format("%.3f", r.frame);
        if (!r.ratio->passes.empty()) out += ", passes " + format("%.3f", r.passes);
        if (r.ratio->paper) out += " (paper, on its own device: " + format("%.2f", *r.ratio->paper) + ")";
        out += "\n";
    }
    if (!tables.empty()) out += "\nTables: computed vs loaded from the cache:\n";
    for (const TableTiming& t : tables)
        out += "  " + t.name + ": computed in " + format("%.2f", t.computeSeconds) + " s, loaded in " + format("%.3f", t.cacheLoadSeconds) + " s\n";
    return out;
}

}  // namespace firmament
