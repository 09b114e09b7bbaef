#pragma once
// A soak run's samples and what they say: whether a quantity grew after the warm-up by more
// than the schedule's bound. The baseline is the sample at the end of the last warm-up loop.
// Counts that are exact (live objects, handles) grow by their largest later sample less the
// baseline: any object or handle more is a leak. Private memory wanders from loop to loop (the
// heaps, the driver's caches, the peak of whichever table the schedule is making again), so its
// growth is its trend: the rise of the least-squares line through the baseline and every later
// sample, over the frames they span. A leak is a rising floor, which the line follows; a wander
// that goes up and comes back down is not growth, however high its peak (the peak is reported).
#include "app/SoakSchedule.h"

#include <nlohmann/json.hpp>

#include <cstdint>
#include <string>
#include <utility>
#include <vector>

namespace firmament {

struct SoakSample {
    long long frame = 0;  // frames rendered when it was taken
    long liveObjects = 0;
    std::vector<std::pair<std::string, long>> liveObjectsByKind;  // "textures", 80, ...
    long handles = 0;
    std::uint64_t privateBytes = 0;
};

struct SoakGrowth {
    std::string quantity;  // "live D3D11 objects", "handles", "private MiB"
    double baseline = 0.0, peak = 0.0, bound = 0.0;
    bool byTrend = false;   // private memory: judged by its fitted rise, not its peak
    double fittedRise = 0.0;
    double growth() const { return byTrend ? fittedRise : peak - baseline; }
    bool exceeded() const { return growth() > bound; }
};

struct SoakVerdict {
    std::string problem;  // empty when the samples could be judged (enough of them)
    std::vector<SoakGrowth> growth;
    bool passed() const;
    std::string summary() const;  // one line per quantity, "handles: 41 -> 41 (bound +0): ok"
};

SoakVerdict judgeSoak(const std::vector<SoakSample>& samples, const SoakSchedule& schedule);
// The report tools/soak keeps: the schedule's loop and bounds, every sample and the verdict.
nlohmann::json soakReport(const SoakSchedule& schedule, const std::vector<SoakSample>& samples, const SoakVerdict& verdict);

}  // namespace firmament
