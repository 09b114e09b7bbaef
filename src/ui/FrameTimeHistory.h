#pragma once
// The last few seconds of frame times, for the Performance panel's graph.
#include <algorithm>
#include <array>
#include <cstddef>

namespace firmament {

class FrameTimeHistory {
public:
    static constexpr size_t kFrames = 240;

    void add(float milliseconds) {
        samples_[next_] = milliseconds;
        next_ = (next_ + 1) % kFrames;
        count_ = std::min(count_ + 1, kFrames);
    }
    // Oldest first; `out` has kFrames entries, the unfilled ones 0.
    std::array<float, kFrames> ordered() const {
        std::array<float, kFrames> out{};
        for (size_t i = 0; i < count_; ++i) out[kFrames - count_ + i] = samples_[(next_ + kFrames - count_ + i) % kFrames];
        return out;
    }
    float maximum() const { return *std::max_element(samples_.begin(), samples_.end()); }

private:
    std::array<float, kFrames> samples_{};
    size_t next_ = 0;
    size_t count_ = 0;
};

}  // namespace firmament
