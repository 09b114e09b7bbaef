#pragma once
// A soak run in progress (--soak): applies the schedule's settings changes before each frame,
// samples the live Direct3D objects, handles and private memory at the end of every loop, and
// at the end judges the growth and writes the report (SoakVerdict).
#include "app/SoakSchedule.h"
#include "app/SoakVerdict.h"
#include "gpu/Device.h"
#include "settings/State.h"

#include <filesystem>
#include <vector>

namespace firmament {

class SoakRun {
public:
    explicit SoakRun(SoakSchedule schedule) : schedule_(std::move(schedule)) {}

    void beforeFrame(long long frame, State& state) const;          // frame: 0-based
    void afterFrame(long long frame, const Device& device);         // samples at a loop's end
    // Judges, writes the report, prints the verdict; the exit code (0 passed, 1 grew).
    int finish(const std::filesystem::path& report) const;

private:
    SoakSchedule schedule_;
    std::vector<SoakSample> samples_;
};

}  // namespace firmament
