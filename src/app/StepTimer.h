#pragma once
// Frame timing: seconds since the last frame, total time, frame count, a smoothed frame
// rate. A fixed step (headless runs, captures) makes every run see the same times.
#include <algorithm>
#include <chrono>
#include <cstdint>
#include <optional>

namespace firmament {

class StepTimer {
public:
    // Longest step a frame may see: after a breakpoint or a stall the simulation does not jump.
    static constexpr double kMaxStepSeconds = 0.25;

    void setFixedStep(std::optional<double> seconds) { fixedStep_ = seconds; }

    void tick() { tick(std::chrono::duration<double>(Clock::now().time_since_epoch()).count()); }

    // nowSeconds: a monotonic clock reading (tests pass their own).
    void tick(double nowSeconds) {
        double step = fixedStep_.value_or(last_ ? nowSeconds - *last_ : 0.0);
        step = std::clamp(step, 0.0, fixedStep_ ? step : kMaxStepSeconds);
        last_ = nowSeconds;
        delta_ = step;
        total_ += step;
        ++frames_;
        if (step > 0.0) {
            const double instant = 1.0 / step;
            fps_ = fps_ == 0.0 ? instant : fps_ + 0.1 * (instant - fps_);  // exponential smoothing
        }
    }

    double deltaSeconds() const { return delta_; }
    double totalSeconds() const { return total_; }
    std::uint64_t frameCount() const { return frames_; }
    double framesPerSecond() const { return fps_; }

private:
    using Clock = std::chrono::steady_clock;
    std::optional<double> fixedStep_;
    std::optional<double> last_;
    double delta_ = 0.0;
    double total_ = 0.0;
    double fps_ = 0.0;
    std::uint64_t frames_ = 0;
};

}  // namespace firmament
