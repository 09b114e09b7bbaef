#pragma once
// A benchmark's scenario file (--benchmark FILE, docs/performance.md): views x settings
// variants x resolutions, each rendered headless for a number of warm-up frames and then a
// number of measured frames. Views and variants are state fragments, as --settings reads them,
// applied in that order over the file's "base" fragment and the program's defaults.
//
//   {"format": 1, "name": "...", "warmupFrames": 5, "measuredFrames": 20,
//    "resolutions": [[1280, 720]], "base": {...},
//    "views": [{"name": "...", "settings": {...}}], "variants": [{"name": "...", "settings": {...}}],
//    "ratios": [{"name": "SS-LUT + MS-Unoccluded / SS-Int", "numerator": "<variant>", "denominator": "<variant>",
//                "passes": ["Sky", "Aerial perspective"], "paper": 0.89}],
//    "tables": true}
//
// Parsing is strict, and every scenario's state is made at load time, so that a bad file is
// bad input (a message naming the problem, exit code 2) before any window or device exists.
#include "settings/State.h"

#include <glm/glm.hpp>
#include <nlohmann/json.hpp>

#include <filesystem>
#include <optional>
#include <string>
#include <vector>

namespace firmament {

struct BenchmarkFragment {
    std::string name;
    nlohmann::json settings;  // a state fragment
};

// The ratio of a numerator variant's time to a denominator variant's, for each view and
// resolution: of the frame, and of the named passes summed.
struct BenchmarkRatio {
    std::string name;
    std::string numerator, denominator;  // variant names
    std::vector<std::string> passes;
    std::optional<double> paper;  // the published value, for comparison
};

struct BenchmarkScenario {
    std::string name;  // "view / variant / WxH"
    std::string view, variant;
    glm::ivec2 resolution{0};
    State state;
};

struct BenchmarkPlan {
    std::string name;
    std::string description;
    int warmupFrames = 5;
    int measuredFrames = 20;
    bool tables = false;  // also time the atmosphere's tables: computing them against loading them from a cache
    std::vector<glm::ivec2> resolutions;
    nlohmann::json base = nlohmann::json::object();
    std::vector<BenchmarkFragment> views, variants;
    std::vector<BenchmarkRatio> ratios;
    State baseState;  // the defaults with "base" applied: the tables timed
    std::vector<BenchmarkScenario> scenarios;  // views x variants x resolutions, resolution outermost
};

// Throws SettingsError ("FILE: key: why") for anything malformed: a missing or mistyped field,
// a resolution out of 16..8192, frame counts out of range, duplicate names, a ratio naming an
// unknown variant, a settings fragment that --settings would refuse.
BenchmarkPlan parseBenchmarkPlan(const nlohmann::json& json, const State& defaults, const std::string& where);
BenchmarkPlan loadBenchmarkPlan(const std::filesystem::path& path, const State& defaults);

}  // namespace firmament
