#include "app/SoakSchedule.h"

#include "core/FileIO.h"
#include "core/SettingsJson.h"
#include "settings/State.h"

#include <nlohmann/json.hpp>

#include <algorithm>
#include <cmath>

namespace firmament {

using nlohmann::json;

namespace {

constexpr int kFormat = 1;
constexpr int kMaxLoopFrames = 1000000;

[[noreturn]] void fail(const std::string& name, const std::string& key, const std::string& why) {
    throw SettingsError(name + ": " + key + ": " + why);
}

int wholeNumber(const json& object, const std::string& key, int low, int high, int fallback, const std::string& name,
                const std::string& path = {}) {
    if (!object.contains(key)) return fallback;
    const json& v = object[key];
    if (!v.is_number_integer() || v.get<long long>() < low || v.get<long long>() > high)
        fail(name, path + key, "expected a whole number from " + std::to_string(low) + " to " + std::to_string(high) + ", got " + v.dump());
    return v.get<int>();
}

SoakBounds readBounds(const json& in, const std::string& name) {
    SoakBounds b;
    if (!in.contains("bounds")) return b;
    const json& o = in["bounds"];
    if (!o.is_object()) fail(name, "bounds", "expected an object");
    for (const auto& [key, value] : o.items())
        if (key != "liveObjects" && key != "handles" && key != "privateMiB") fail(name, "bounds." + key, "is not a bound (liveObjects, handles, privateMiB)");
    b.liveObjects = wholeNumber(o, "liveObjects", 0, 1000000, static_cast<int>(b.liveObjects), name, "bounds.");
    b.handles = wholeNumber(o, "handles", 0, 1000000, static_cast<int>(b.handles), name, "bounds.");
    if (o.contains("privateMiB")) {
        const json& v = o["privateMiB"];
        if (!v.is_number() || !std::isfinite(v.get<double>()) || v.get<double>() < 0.0)
            fail(name, "bounds.privateMiB", "expected a number of MiB, 0 or more, got " + v.dump());
        b.privateMiB = v.get<double>();
    }
    return b;
}

// Each assignment tried on `state` in order; a bad one is named where it stands in the file.
void tryAssignments(State& state, const std::vector<std::string>& assignments, const std::string& name, const std::string& where) {
    for (const std::string& assignment : assignments) {
        try {
            assignSetting(assignment, state.sections());
        } catch (const SettingsError& e) {
            fail(name, where, assignment + ": " + e.what());
        }
    }
}

}  // namespace

std::vector<std::string> SoakSchedule::assignmentsAt(long long frame) const {
    const int inLoop = static_cast<int>(frame % loopFrames);
    std::vector<std::string> due;
    for (const SoakStep& step : steps)
        if (step.frame == inLoop) due.insert(due.end(), step.assignments.begin(), step.assignments.end());
    return due;
}

SoakSchedule SoakSchedule::parse(std::span<const std::uint8_t> bytes, const std::string& name) {
    json in;
    try {
        in = json::parse(bytes.begin(), bytes.end());
    } catch (const json::exception& e) {  // parse_error, or out_of_range for a number too large for a double
        throw SettingsError(name + ": not valid JSON: " + e.what());
    }
    if (!in.is_object()) fail(name, "(top)", "expected a JSON object");
    for (const auto& [key, value] : in.items())
        if (key != "format" && key != "description" && key != "loopFrames" && key != "warmupLoops" && key != "bounds" && key != "base" && key != "steps")
            fail(name, key, "is not a field of a soak schedule");
    if (wholeNumber(in, "format", 0, 1000, kFormat, name) != kFormat) fail(name, "format", "this version reads format " + std::to_string(kFormat));

    SoakSchedule s;
    s.loopFrames = wholeNumber(in, "loopFrames", 1, kMaxLoopFrames, s.loopFrames, name);
    s.warmupLoops = wholeNumber(in, "warmupLoops", 0, 1000, s.warmupLoops, name);
    s.bounds = readBounds(in, name);

    State scratch;  // every assignment is tried, in the order the run applies them
    const json& base = in.contains("base") ? in["base"] : json::array();
    if (!base.is_array()) fail(name, "base", "expected a list of \"section.key=value\"");
    for (const json& assignment : base) {
        if (!assignment.is_string()) fail(name, "base", "expected \"section.key=value\", got " + assignment.dump());
        s.base.push_back(assignment.get<std::string>());
    }
    tryAssignments(scratch, s.base, name, "base");

    const json& steps = in.contains("steps") ? in["steps"] : json::array();
    if (!steps.is_array()) fail(name, "steps", "expected a list of {\"frame\": N, \"set\": [\"section.key=value\", ...]}");
    for (size_t i = 0; i < steps.size(); ++i) {
        const std::string path = "steps[" + std::to_string(i) + "].";
        const json& entry = steps[i];
        if (!entry.is_object()) fail(name, path, "expected an object");
        for (const auto& [key, value] : entry.items())
            if (key != "frame" && key != "set") fail(name, path + key, "is not a field of a step (frame, set)");
        if (!entry.contains("frame")) fail(name, path + "frame", "is missing");
        SoakStep step;
        step.frame = wholeNumber(entry, "frame", 0, s.loopFrames - 1, 0, name, path);
        if (!s.steps.empty() && step.frame < s.steps.back().frame)
            fail(name, path + "frame", std::to_string(step.frame) + " comes before the step above (" + std::to_string(s.steps.back().frame) + ")");
        const json& set = entry.contains("set") ? entry["set"] : json();
        if (!set.is_array() || set.empty()) fail(name, path + "set", "expected a non-empty list of \"section.key=value\"");
        for (const json& assignment : set) {
            if (!assignment.is_string()) fail(name, path + "set", "expected \"section.key=value\", got " + assignment.dump());
            step.assignments.push_back(assignment.get<std::string>());
        }
        tryAssignments(scratch, step.assignments, name, path + "set");
        s.steps.push_back(std::move(step));
    }
    return s;
}

SoakSchedule SoakSchedule::load(const std::filesystem::path& path) {
    const auto bytes = readFileBytes(path);
    return parse(bytes, path.string());
}

}  // namespace firmament
