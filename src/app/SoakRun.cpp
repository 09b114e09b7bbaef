#include "app/SoakRun.h"

#include "app/ProcessCounters.h"
#include "core/FileIO.h"
#include "core/Log.h"

#include <cstdio>

namespace firmament {

void SoakRun::beforeFrame(long long frame, State& state) const {
    if (frame == 0 && !schedule_.base.empty()) applyAssignments(state, schedule_.base);
    const std::vector<std::string> due = schedule_.assignmentsAt(frame);
    if (!due.empty()) applyAssignments(state, due);  // checked when the schedule was loaded
}

void SoakRun::afterFrame(long long frame, const Device& device) {
    if (!schedule_.samplesAfter(frame)) return;
    const LiveObjectCounts objects = device.liveObjects();
    const ProcessCounters process = sampleProcessCounters();
    SoakSample s;
    s.frame = frame + 1;
    s.liveObjects = objects.total();
    for (int k = 0; k < kGpuObjectKinds; ++k) s.liveObjectsByKind.emplace_back(std::string(kGpuObjectKindNames[k]), objects.byKind[k]);
    s.handles = process.handles;
    s.privateBytes = process.privateBytes;
    samples_.push_back(s);
    char memory[32];
    std::snprintf(memory, sizeof memory, "%.1f MiB", static_cast<double>(s.privateBytes) / (1024.0 * 1024.0));
    log::info("soak: frame " + std::to_string(s.frame) + ": live D3D11 objects " + objects.describe() + "; handles " +
              std::to_string(s.handles) + "; private " + memory);
}

int SoakRun::finish(const std::filesystem::path& report) const {
    const SoakVerdict verdict = judgeSoak(samples_, schedule_);
    writeFileText(report, soakReport(schedule_, samples_, verdict).dump(2) + "\n");
    std::string text = "soak: " + std::to_string(samples_.size()) + " samples, " + std::to_string(schedule_.warmupLoops) +
                       " warm-up loop(s) of " + std::to_string(schedule_.loopFrames) + " frames\n";
    const std::string summary = verdict.summary();
    for (size_t start = 0; start < summary.size();) {  // each line of the summary, indented under it
        const size_t end = summary.find('\n', start);
        text += "soak:   " + summary.substr(start, end == std::string::npos ? std::string::npos : end - start) + "\n";
        start = end == std::string::npos ? summary.size() : end + 1;
    }
    std::fputs(text.c_str(), stdout);
    std::printf("soak: %s; report written to %s\n", verdict.passed() ? "passed" : "FAILED", report.string().c_str());
    std::fflush(stdout);
    if (!verdict.passed()) log::error("soak: " + (verdict.problem.empty() ? std::string("a quantity grew beyond its bound") : verdict.problem));
    return verdict.passed() ? 0 : 1;
}

}  // namespace firmament
