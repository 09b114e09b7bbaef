#pragma once
// The command line: parsed into Options, or an error message naming the problem. Pure (no
// Windows calls), so it is unit-tested on its own.
#include "gpu/DeviceOptions.h"

#include <filesystem>
#include <optional>
#include <string>
#include <vector>

namespace firmament {

struct Options {
    bool headless = false;         // no visible window; WARP unless --hardware or --adapter
    DriverType driver = DriverType::Hardware;
    std::optional<unsigned> adapter;
    std::optional<int> frames;     // stop after this many frames (headless default: 30)
    int width = 1280;
    int height = 720;
    bool vsync = true;
    std::optional<std::filesystem::path> capture;  // PNG path; the EXR goes beside it
    std::optional<std::filesystem::path> shaderDir;
    bool help = false;
    bool version = false;

    int frameCount() const { return frames.value_or(headless ? 30 : 0); }  // 0: until closed
    std::filesystem::path capturePng() const;
    std::filesystem::path captureExr() const;
};

struct ParsedCommandLine {
    Options options;
    std::string error;  // empty when the command line is valid
};

ParsedCommandLine parseCommandLine(const std::vector<std::string>& arguments);  // without argv[0]
std::string usageText();

}  // namespace firmament
