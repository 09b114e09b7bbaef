#pragma once
// The GUI's content: the panel chosen in the drop-down at the top (Basic, Additional, Tone
// mapping, Performance), the shader-error window and the F1 help window. What the GUI asks
// the program to do (full screen, reload, save, load) comes back as GuiRequests.
#include "settings/State.h"
#include "gpu/GpuProfiler.h"
#include "postfx/ExposureReading.h"
#include "ui/FrameTimeHistory.h"

#include <map>
#include <optional>
#include <string>
#include <vector>

namespace firmament {

struct FrameStats {
    double cpuFrameMs = 0.0;
    double framesPerSecond = 0.0;
    int width = 0;
    int height = 0;
    std::string adapter;
};

struct GuiModel {
    State& state;
    FrameStats stats;
    const std::vector<PassTiming>& timings;
    const FrameTimeHistory& frameTimes;
    const std::map<std::string, std::string>& shaderErrors;
    std::string shaderCompiler;        // the hot-reload backend's name, empty when off
    std::vector<std::string> devices;  // connected HID devices and pads
    std::string notice;                // the last save / load / reload message
    bool noticeIsError = false;
    ExposureReading exposure;          // what the tone mapping applied, a few frames ago
    std::optional<double> atmosphereProgress;  // 0..1 while the atmosphere's tables are recomputed
    std::optional<double> cloudTableProgress;  // 0..1 while the cloud particle's tables are computed
    std::string cloudBlending;                 // how the clouds' particles are blended, and what did not fit
};

struct GuiRequests {
    bool toggleFullScreen = false;
    bool reloadShaders = false;
    bool saveState = false;
    bool loadState = false;
};

GuiRequests drawGui(GuiModel& model);

}  // namespace firmament
