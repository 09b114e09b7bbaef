#pragma once
// Runs firmament.exe headless for one frame and reads back the radiance it captured (the EXR
// beside the PNG, before tone mapping): the app tests' way of looking at a frame.
#include <filesystem>
#include <string>
#include <vector>

namespace firmament::test {

// `--headless --frames 1 --resolution WxH`, `--set` each of `settings`, `--capture folder/name.png`.
// The EXR's RGB, row by row; empty (with a test failure naming the output) when the run fails.
std::vector<float> captureRadiance(const std::filesystem::path& folder, const std::string& name, const std::vector<std::wstring>& settings, int width,
                                   int height);

}  // namespace firmament::test
