#pragma once
// The program: the window, the device and swap chain, input, the frame loop, flights,
// captures and benchmarks. The frame itself, every technique and its order, is the Renderer's.
#include "app/BenchmarkPlan.h"
#include "app/CommandLine.h"
#include "app/FlightPath.h"
#include "app/StepTimer.h"
#include "app/Window.h"
#include "gpu/Device.h"
#include "gpu/ShaderLibrary.h"
#include "gpu/SwapChain.h"
#include "input/HidDevices.h"
#include "input/KeyboardMouse.h"
#include "input/XInputPads.h"
#include "render/Renderer.h"
#include "settings/State.h"
#include "ui/FrameTimeHistory.h"
#include "ui/Overlay.h"

#include <memory>

namespace firmament {

class App {
public:
    // `flight`: a camera path to play back first (--flight).
    App(const Options& options, const State& state, std::optional<FlightPath> flight);  // throws Error
    int run();                                         // returns the exit code
    // --benchmark: runs the plan's scenarios, prints the table, writes the JSON; the exit code.
    int runBenchmark(const BenchmarkPlan& plan);

private:
    void update();
    void renderFrame(bool drawGui);
    // The frame into --capture's files, or with `name` (a flight keyframe's) into PATH-name's.
    void captureFrame(const std::string& name = {});
    void keepCameraAboveGround();
    void printTimings();
    void onKey(WPARAM key);
    void onInput(UINT message, WPARAM wParam, LPARAM lParam);
    void handleRequests(const GuiRequests& requests);
    void reloadShaders();
    void saveState();
    void loadState();
    void setNotice(std::string text, bool isError);
    ID3D11RenderTargetView* outputTarget() const;
    ID3D11Texture2D* outputTexture() const;

    Options options_;
    State state_;
    std::unique_ptr<ShaderCompiler> shaderSource_;  // handed to shaders_ once the device exists
    std::unique_ptr<Window> window_;
    Device device_;
    std::unique_ptr<SwapChain> swapChain_;  // null when headless
    ShaderLibrary shaders_;
    Renderer renderer_;
    std::unique_ptr<Overlay> overlay_;

    KeyboardMouse keyboardMouse_;
    HidDevices hidDevices_;
    XInputPads xinputPads_;

    std::optional<FlightPath> flight_;
    bool flightDone_ = false;  // the flight's last keyframe has been shown
    double flightShown_ = -1.0;  // the flight's time the last frame showed (-1 before the first)
    std::vector<std::string> dueCaptures_;  // this frame's flight captures
    FlightPath recording_;
    StepTimer timer_;
    FrameTimeHistory frameTimes_;
    double lastSourcePoll_ = 0.0;
    std::string notice_;
    bool noticeIsError_ = false;
};

}  // namespace firmament
