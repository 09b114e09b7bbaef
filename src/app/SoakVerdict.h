#pragma once
// A soak run's samples and what they say: whether a quantity grew after the warm-up by more
// than the schedule's bound. The baseline is the sample at the end of the last warm-up loop;
// the growth is the largest later sample less the baseline (a leak shows as a peak that keeps
// rising; a quantity that goes up and comes back down again is not growth).
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
    double growth() const { return peak - baseline; }
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
