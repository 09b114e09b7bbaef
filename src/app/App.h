#pragma once
// The program: the window, the device and swap chain, input, the frame loop, flights,
// captures and benchmarks. The frame itself, every technique and its order, is the Renderer's.
// Its members are defined by job: the loop (App.cpp), input bindings (AppInput.cpp), one frame
// and its GUI model (AppFrame.cpp), captures (AppCaptures.cpp), the benchmark and printed
// timings (AppBenchmark.cpp); what is made on the device is DeviceResources; a soak's driver
// is SoakRun.
#include "app/BenchmarkPlan.h"
#include "app/CaptureBatch.h"
#include "app/CommandLine.h"
#include "app/DeviceResources.h"
#include "app/FlightPath.h"
#include "app/SoakRun.h"
#include "app/StepTimer.h"
#include "app/Window.h"
#include "input/HidDevices.h"
#include "input/KeyboardMouse.h"
#include "input/XInputPads.h"
#include "render/Renderer.h"
#include "settings/State.h"
#include "ui/FrameTimeHistory.h"
#include "ui/Overlay.h"

#include <chrono>
#include <memory>

namespace firmament {

class App {
public:
    // `flight`: a camera path to play back first (--flight); `soak`: the schedule of a soak run
    // (--soak), which plays the flight in a loop.
    App(const Options& options, const State& state, std::optional<FlightPath> flight,
        std::optional<SoakSchedule> soak = std::nullopt);  // throws Error
    int run();                                         // returns the exit code
    // --benchmark: runs the plan's scenarios, prints the table, writes the JSON; the exit code.
    int runBenchmark(const BenchmarkPlan& plan);
    // --batch FILE: captures each view from a fresh start (CaptureBatch.h); the exit code.
    int runBatch(const std::vector<CaptureItem>& views);
    // --batch -: the same for requests read one a line from standard input until it ends, each
    // answered on standard output; a refused request is answered and the next one is read.
    int serveCaptures(const CaptureDefaults& defaults);

private:
    // The frame loop: `frames` frames (0: until the window closes), with the flight's and
    // --capture's captures due in them.
    void renderFrames(int frames);
    // One view of a batch: the state, the clock and the renderer as a fresh start has them,
    // then its frames, the last captured into its files.
    void captureView(const CaptureItem& view);
    void update();
    void renderFrame(bool drawGui);
    // The frame into --capture's files, or with `name` (a flight keyframe's) into PATH-name's.
    void captureFrame(const std::string& name = {});
    // F12: the frame into PATH-shot-N's files (firmament-shot-N without --capture); a failure is
    // a notice and the program goes on.
    void captureShot();
    // Waits, drawing nothing, while the window is minimized; logs how long.
    void sleepWhileMinimized();
    // The swap chain and the renderer's targets follow the window's client area (at least 16 a side).
    void followWindowSize();
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
    // Destroys every GPU resource and makes them again on a new device (`why`: the loss's name).
    void recoverFromDeviceLoss(const std::string& why);

    Options options_;
    State state_;
    std::unique_ptr<ShaderCompiler> shaderSource_;  // opened before the window (a bad folder fails fast)
    std::unique_ptr<Window> window_;
    std::unique_ptr<DeviceResources> gpu_;
    int deviceLosses_ = 0;

    KeyboardMouse keyboardMouse_;
    HidDevices hidDevices_;
    XInputPads xinputPads_;

    std::optional<FlightPath> flight_;
    bool flightDone_ = false;  // the flight's last keyframe has been shown
    double flightShown_ = -1.0;  // the flight's time the last frame showed (-1 before the first)
    double flightStart_ = 0.0;   // the clock's time at the flight's first frame, its time zero
    std::vector<std::string> dueCaptures_;  // this frame's flight captures
    bool shotRequested_ = false;            // F12 was pressed: capture the next frame
    int shotsTaken_ = 0;
    std::optional<SoakRun> soak_;
    FlightPath recording_;
    StepTimer timer_;
    FrameTimeHistory frameTimes_;
    std::chrono::steady_clock::time_point lastSourcePoll_{};  // wall-clock time of the last look at the shader files
    std::string notice_;
    bool noticeIsError_ = false;
};

}  // namespace firmament
