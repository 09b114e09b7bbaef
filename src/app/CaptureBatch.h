#pragma once
// A batch of headless captures rendered by one process (--batch), each from a fresh start: the
// golden images and the capture tests use it instead of one firmament.exe per view
// (docs/building.md, "Batched captures").
//
// --batch FILE reads a list of views (tests/golden/views.json is one; other fields are ignored):
//
//   {"resolution": [256, 144], "frames": 3,
//    "views": [{"name": "sky", "settings": {...}, "set": ["sun.elevation=5"],
//               "resolution": [96, 54], "frames": 1, "captureUi": true}]}
//
// Each view's state is the program's defaults, then --settings and --set, then the view's
// "settings" fragment and its "set" assignments. Its capture is --capture's PATH-name.png and
// .exr. "resolution" and "frames" default to the file's, then to --resolution and --frames;
// "captureUi" (the GUI drawn into the capture, as --capture-ui) to the file's, then to
// --capture-ui.
//
// --batch - reads one view a line from standard input, the same fields plus "capture" (the PNG's
// path) and an optional "id", and answers each on standard output with "batch: done ID" or
// "batch: refused ID: why" once its files are written. It ends at the end of its input.
#include "settings/State.h"

#include <nlohmann/json.hpp>

#include <filesystem>
#include <string>
#include <vector>

namespace firmament {

struct CaptureItem {
    std::string id;  // the view's name, or the request's "id"
    State state;
    int width = 0, height = 0;
    int frames = 1;
    bool captureUi = false;     // the GUI in the capture (--capture-ui)
    std::filesystem::path png;  // the EXR goes beside it
};

// What a view falls back on: the program's state and its command line's size and frame count.
struct CaptureDefaults {
    State state;
    int width = 0, height = 0;
    int frames = 1;
    bool captureUi = false;
    std::filesystem::path capture;  // --capture's PATH (a batch file's views are PATH-name.png)
};

// A batch file's views, in order. Strict: throws SettingsError ("WHERE: views[2].frames: why")
// for a missing or mistyped field, a duplicate or unusable name, a size or frame count out of
// range, or settings --settings or --set would refuse.
std::vector<CaptureItem> parseCaptureBatch(const nlohmann::json& json, const CaptureDefaults& defaults, const std::string& where);
std::vector<CaptureItem> loadCaptureBatch(const std::filesystem::path& path, const CaptureDefaults& defaults);

// One line of --batch -: throws SettingsError as above, naming the request's id where it has one.
CaptureItem parseCaptureRequest(const std::string& line, const CaptureDefaults& defaults);
// The request's "id" (else its "name") as the answer names it; "?" when the line has neither.
std::string captureRequestId(const std::string& line);

}  // namespace firmament
