#pragma once
// Captures one headless frame (HeadlessCapture.h) and reads back the radiance it captured (the
// EXR beside the PNG, before tone mapping): the app tests' way of looking at a frame.
#include <filesystem>
#include <string>
#include <vector>

namespace firmament::test {

// The last of `frames` frames at width x height with `settings` (--set assignments) into
// folder/name.png and .exr. The EXR's RGB, row by row; empty (with a test failure naming the
// output) when the run fails.
std::vector<float> captureRadiance(const std::filesystem::path& folder, const std::string& name, const std::vector<std::wstring>& settings, int width,
                                   int height, int frames = 1);

}  // namespace firmament::test
