#pragma once
// The command line: parsed into Options, or an error message naming the problem. One table of
// options (CommandLine.cpp) drives both the parser and the usage text, so the two cannot
// disagree. Pure (no Windows calls), so it is unit-tested on its own.
#include "gpu/DeviceOptions.h"

#include <filesystem>
#include <optional>
#include <string>
#include <vector>

namespace firmament {

// The frame's size: --resolution's range, and what a window's client area is drawn at (a window
// smaller than 16 pixels a side is drawn at 16 and stretched by the swap chain).
inline constexpr int kMinFrameSide = 16;
inline constexpr int kMaxFrameSide = 16384;

struct Options {
    bool headless = false;         // no visible window; WARP unless --hardware or --adapter
    DriverType driver = DriverType::Hardware;
    std::optional<unsigned> adapter;
    std::optional<int> frames;     // stop after this many frames (headless default: 30)
    int width = 1280;
    int height = 720;
    std::optional<bool> vsync;     // overrides display.vsync
    std::optional<std::filesystem::path> capture;  // PNG path; the EXR goes beside it (F12's shots too)
    bool captureUi = false;        // the GUI is left out of captures unless asked for
    bool hdrFloat32 = false;       // the HDR frame (and its EXR) in 32-bit floats, for measurement
    std::optional<std::filesystem::path> shaderDir;
    std::optional<std::filesystem::path> shaderSource;  // HLSL folder for hot reload
    std::string shaderCompiler = "auto";                // auto|d3dcompile|vkd3d|fxc|none
    std::optional<std::filesystem::path> settingsFile;  // loaded at start
    std::vector<std::string> assignments;               // --set section.key=value, in order
    std::filesystem::path stateFile = "firmament-state.json";  // F5 saves it, F9 loads it
    std::optional<std::filesystem::path> flight;        // camera path played back
    std::optional<std::filesystem::path> recordFlight;  // where the flown path is written
    std::optional<std::filesystem::path> exportLuts;    // write the atmosphere's tables here as EXR
    std::optional<std::filesystem::path> cacheDir;      // the atmosphere's table cache (default: per user)
    bool noCache = false;                               // compute the tables every run
    // Every frame advances the clock by exactly this (seconds; headless runs: 1/60). 0 stops it:
    // the clouds' wind and the sun hold still, so a window's frames match a headless capture.
    std::optional<double> timeStep;
    std::optional<int> simulateDeviceLoss;              // after this frame (1-based), recover as from a removed device
    std::optional<std::filesystem::path> generateCloudScattering;  // compute the cloud particle's scattering table into this file and exit
    std::optional<std::filesystem::path> generateDeckDiffusion;    // compute deck diffusion's table into this file and exit
    std::optional<std::filesystem::path> benchmark;     // a scenario file to run (implies headless)
    std::optional<std::filesystem::path> benchmarkOutput;  // the results' JSON (default benchmark-results.json)
    std::optional<std::filesystem::path> batch;       // a list of views to capture, or "-" for requests on standard input (implies headless)
    std::optional<std::filesystem::path> soak;        // a soak schedule (tools/soak)
    std::optional<std::filesystem::path> soakReport;  // the soak's samples and verdict (default soak-report.json)
    bool help = false;
    bool version = false;

    // 0: until closed. A soak's default is the length tools/soak runs.
    int frameCount() const { return frames.value_or(soak ? 10000 : headless ? 30 : 0); }
    // The capture's files; with `name` (a flight keyframe's capture, F12's "shot-N"), PATH-name.png
    // and .exr. Without --capture, F12's shots go to firmament-shot-N.png in the current folder.
    std::filesystem::path capturePng(const std::string& name = {}) const;
    std::filesystem::path captureExr(const std::string& name = {}) const;
    std::filesystem::path benchmarkResults() const { return benchmarkOutput.value_or("benchmark-results.json"); }
    std::filesystem::path soakResults() const { return soakReport.value_or("soak-report.json"); }
};

struct ParsedCommandLine {
    Options options;
    std::string error;  // empty when the command line is valid
};

ParsedCommandLine parseCommandLine(const std::vector<std::string>& arguments);  // without argv[0]
std::string usageText();

// An option of the table, as the tests see it: its name, its value's placeholder in the usage
// text (empty for a flag) and a valid value.
struct CommandLineOption {
    std::string name;
    std::string value;
    std::string example;
};
std::vector<CommandLineOption> commandLineOptions();

}  // namespace firmament
