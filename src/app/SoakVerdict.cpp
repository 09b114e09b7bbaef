#include "app/SoakVerdict.h"

#include <algorithm>
#include <cstdio>

namespace firmament {

namespace {

constexpr double kMiB = 1024.0 * 1024.0;

template <typename Value>
SoakGrowth growthOf(const std::string& quantity, const std::vector<SoakSample>& samples, size_t baseline, double bound, Value value) {
    SoakGrowth g{quantity, value(samples[baseline]), value(samples[baseline]), bound};
    for (size_t i = baseline + 1; i < samples.size(); ++i) g.peak = std::max(g.peak, value(samples[i]));
    return g;
}

// The rise of the least-squares line y = a + b frame through samples[baseline..], over the frames
// they span: b (last frame - baseline's frame). With one later sample it is that sample less the
// baseline.
template <typename Value>
double fittedRise(const std::vector<SoakSample>& samples, size_t baseline, Value value) {
    const double n = static_cast<double>(samples.size() - baseline);
    double meanX = 0.0, meanY = 0.0;
    for (size_t i = baseline; i < samples.size(); ++i) {
        meanX += static_cast<double>(samples[i].frame) / n;
        meanY += value(samples[i]) / n;
    }
    double covariance = 0.0, variance = 0.0;
    for (size_t i = baseline; i < samples.size(); ++i) {
        const double dx = static_cast<double>(samples[i].frame) - meanX;
        covariance += dx * (value(samples[i]) - meanY);
        variance += dx * dx;
    }
    if (variance <= 0.0) return 0.0;
    return covariance / variance * static_cast<double>(samples.back().frame - samples[baseline].frame);
}

std::string number(double value, bool fractional) {
    char text[32];
    std::snprintf(text, sizeof text, fractional ? "%.1f" : "%.0f", value);
    return text;
}

}  // namespace

bool SoakVerdict::passed() const {
    return problem.empty() && std::none_of(growth.begin(), growth.end(), [](const SoakGrowth& g) { return g.exceeded(); });
}

std::string SoakVerdict::summary() const {
    if (!problem.empty()) return problem;
    std::string text;
    for (const SoakGrowth& g : growth) {
        const bool mib = g.quantity == "private MiB";
        text += g.quantity + ": " + number(g.baseline, mib) + " after the warm-up, at most " + number(g.peak, mib) + " later (" +
                (g.byTrend ? "fitted rise " : "growth ") + number(g.growth(), mib) + ", bound " + number(g.bound, mib) + "): " +
                (g.exceeded() ? "GREW" : "ok") + "\n";
    }
    return text;
}

SoakVerdict judgeSoak(const std::vector<SoakSample>& samples, const SoakSchedule& schedule) {
    SoakVerdict v;
    // Sample k is taken at the end of loop k + 1; the baseline ends the warm-up.
    const size_t baseline = schedule.warmupLoops > 0 ? static_cast<size_t>(schedule.warmupLoops - 1) : 0;
    if (samples.size() < static_cast<size_t>(schedule.samplesNeeded())) {
        v.problem = "too few samples to judge: " + std::to_string(samples.size()) + " loops of " + std::to_string(schedule.loopFrames) +
                    " frames were run, and this schedule needs " + std::to_string(schedule.samplesNeeded()) + " (" +
                    std::to_string(schedule.framesNeeded()) + " frames; pass more --frames)";
        return v;
    }
    const SoakBounds& b = schedule.bounds;
    v.growth.push_back(growthOf("live D3D11 objects", samples, baseline, static_cast<double>(b.liveObjects),
                                [](const SoakSample& s) { return static_cast<double>(s.liveObjects); }));
    v.growth.push_back(growthOf("handles", samples, baseline, static_cast<double>(b.handles),
                                [](const SoakSample& s) { return static_cast<double>(s.handles); }));
    const auto mib = [](const SoakSample& s) { return static_cast<double>(s.privateBytes) / kMiB; };
    SoakGrowth memory = growthOf("private MiB", samples, baseline, b.privateMiB, mib);
    memory.byTrend = true;
    memory.fittedRise = fittedRise(samples, baseline, mib);
    v.growth.push_back(memory);
    return v;
}

nlohmann::json soakReport(const SoakSchedule& schedule, const std::vector<SoakSample>& samples, const SoakVerdict& verdict) {
    using nlohmann::json;
    json report;
    report["loopFrames"] = schedule.loopFrames;
    report["warmupLoops"] = schedule.warmupLoops;
    report["bounds"] = {{"liveObjects", schedule.bounds.liveObjects}, {"handles", schedule.bounds.handles}, {"privateMiB", schedule.bounds.privateMiB}};
    json list = json::array();
    for (const SoakSample& s : samples) {
        json kinds = json::object();
        for (const auto& [kind, count] : s.liveObjectsByKind) kinds[kind] = count;
        list.push_back({{"frame", s.frame},
                        {"liveObjects", s.liveObjects},
                        {"liveObjectsByKind", kinds},
                        {"handles", s.handles},
                        {"privateBytes", s.privateBytes}});
    }
    report["samples"] = list;
    json growth = json::array();
    for (const SoakGrowth& g : verdict.growth)
        growth.push_back({{"quantity", g.quantity}, {"baseline", g.baseline}, {"peak", g.peak}, {"growth", g.growth()},
                          {"measure", g.byTrend ? "fitted rise" : "peak less baseline"}, {"bound", g.bound}, {"exceeded", g.exceeded()}});
    report["growth"] = growth;
    if (!verdict.problem.empty()) report["problem"] = verdict.problem;
    report["passed"] = verdict.passed();
    return report;
}

}  // namespace firmament
