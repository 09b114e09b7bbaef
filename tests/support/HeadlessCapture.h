#pragma once
// Headless captures for the app tests. Every capture of a test process goes through one
// firmament.exe --batch - (started at the first capture and kept), each rendered from a fresh
// start (Renderer::startOver), so that a test of ten views pays for one program start, one
// device and one loading of the tables, not ten (docs/building.md, "Batched captures").
// FIRMAMENT_TEST_SEPARATE_CAPTURES=1 starts one firmament.exe per capture instead, as the
// tests did before: the check that both give the same files.
#include "support/Process.h"

#include <nlohmann/json.hpp>

#include <filesystem>
#include <string>
#include <vector>

namespace firmament::test {

struct HeadlessCapture {
    nlohmann::json fragment = nlohmann::json::object();  // a state fragment, as --settings reads it, over the defaults (null: none)
    std::vector<std::wstring> settings;  // --set assignments, in order, after the fragment
    int width = 0, height = 0;
    int frames = 1;
    std::filesystem::path png;  // the EXR is written beside it
    bool captureUi = false;     // the GUI drawn into the capture (--capture-ui)
};

// Renders and writes the capture; exit code 0 and the program's output for this capture, or
// non-zero and what it said (a refused view, or the program's failure).
ProcessResult captureHeadless(const HeadlessCapture& capture);

// True when FIRMAMENT_TEST_SEPARATE_CAPTURES=1 (one process per capture).
bool separateCaptures();

}  // namespace firmament::test
