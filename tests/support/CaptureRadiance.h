#pragma once
// Captures one headless frame (HeadlessCapture.h) and reads back the radiance it captured (the
// EXR beside the PNG, before tone mapping): the app tests' way of looking at a frame.
#include <filesystem>
#include <string>
#include <vector>

namespace firmament {
struct ExrFile;
}

namespace firmament::test {

// Channel `c` (0 R, 1 G, 2 B, 3 A) of pixel (x, y) of a captured EXR (half floats), as a float.
float exrChannel(const ExrFile& file, int x, int y, int c);
// The captured EXR's RGB, row by row.
std::vector<float> exrRgb(const ExrFile& file);

// The last of `frames` frames at width x height with `settings` (--set assignments) into
// folder/name.png and .exr. The EXR's RGB, row by row; empty (with a test failure naming the
// output) when the run fails.
std::vector<float> captureRadiance(const std::filesystem::path& folder, const std::string& name, const std::vector<std::wstring>& settings, int width,
                                   int height, int frames = 1);

}  // namespace firmament::test
