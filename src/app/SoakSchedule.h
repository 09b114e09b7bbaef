#pragma once
// A soak run's schedule (--soak FILE, tools/soak, docs/reliability.md): settings assignments,
// as --set takes them, at frames of a loop that repeats for the whole run, and the growth each
// sampled quantity may show after the warm-up loops.
//
//   {"format": 1, "loopFrames": 240, "warmupLoops": 1,
//    "bounds": {"liveObjects": 0, "handles": 0, "privateMiB": 16},
//    "base": ["clouds.rings=1", ...],
//    "steps": [{"frame": 2, "set": ["clouds.enabled=off"]}, {"frame": 4, "set": [...]}, ...]}
//
// "base" is applied once, before the first frame: the workload's size (the steps are what is
// tried), so that a soak of thousands of frames fits in a CPU renderer's hour.
// The resources are sampled at the end of every loop, where the state is the same each time: a
// step sets keys to values, so from the second loop on every loop starts as the one before did.
// Every assignment is checked at load time against the settings, so a bad file is bad input
// (exit code 2) before any window or device exists.
#include <cstdint>
#include <filesystem>
#include <span>
#include <string>
#include <vector>

namespace firmament {

struct SoakBounds {
    long liveObjects = 0;     // Direct3D 11 objects made by the program and alive
    long handles = 0;         // the process's kernel handles
    double privateMiB = 16.0; // the process's private (committed, not shared) memory
};

struct SoakStep {
    int frame = 0;                         // in the loop, 0 .. loopFrames - 1
    std::vector<std::string> assignments;  // "section.key=value", applied in order
};

struct SoakSchedule {
    int loopFrames = 240;
    int warmupLoops = 1;
    SoakBounds bounds;
    std::vector<std::string> base;  // applied once, before the first frame
    std::vector<SoakStep> steps;    // in frame order

    // The assignments due before run frame `frame` (0-based): the steps at frame % loopFrames.
    std::vector<std::string> assignmentsAt(long long frame) const;
    // Whether the resources are sampled after run frame `frame`: the loop's last frame.
    bool samplesAfter(long long frame) const { return (frame + 1) % loopFrames == 0; }
    // The samples a verdict needs: the baseline at the end of the warm-up (or the first loop's
    // end without one), then one more; and the frames that takes.
    int samplesNeeded() const { return (warmupLoops > 0 ? warmupLoops : 1) + 1; }
    long long framesNeeded() const { return static_cast<long long>(samplesNeeded()) * loopFrames; }

    // Strict, as the benchmark's scenario files: throws SettingsError "name: key: why".
    static SoakSchedule parse(std::span<const std::uint8_t> bytes, const std::string& name);
    static SoakSchedule load(const std::filesystem::path& path);
};

}  // namespace firmament
