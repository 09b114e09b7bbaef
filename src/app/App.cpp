// The program's loop (App.h): construction, the frames one after another (input and flight,
// then the frame, captures and Present), a minimized window, the window's size, and the answer
// to a lost device. The device itself is DeviceResources.cpp's; the keys AppInput.cpp's; the
// frame and its GUI model AppFrame.cpp's; captures AppCaptures.cpp's; the benchmark and the
// printed timings AppBenchmark.cpp's.
#include "app/App.h"

#include "app/ProcessCounters.h"
#include "atmosphere/SunAnimation.h"
#include "core/Error.h"
#include "core/FileIO.h"
#include "core/Log.h"
#include "FirmamentVersion.h"

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <cstring>
#include <utility>

namespace firmament {

namespace {

// Shader files are checked four times a second of wall-clock time (not the frame clock, which
// --time-step 0 holds still).
constexpr auto kSourcePollInterval = std::chrono::milliseconds(250);

const Options& checkedOptions(const Options& options) {
    if (options.capture) {
        ensureWritable(options.capturePng());
        ensureWritable(options.captureExr());
    }
    return options;
}

}  // namespace

App::App(const Options& options, const State& state, std::optional<FlightPath> flight, std::optional<SoakSchedule> soak)
    : options_(checkedOptions(options)),
      state_(state),
      shaderSource_(openShaderFolder(options_)),
      window_(std::make_unique<Window>(L"Firmament " + std::wstring(kFirmamentVersion, kFirmamentVersion + std::strlen(kFirmamentVersion)),
                                       options_.width, options_.height, !options_.headless,
                                       Window::Callbacks{&Overlay::handleMessage, [this](WPARAM key) { onKey(key); },
                                                         [this](UINT m, WPARAM w, LPARAM l) { onInput(m, w, l); }})),
      gpu_(std::make_unique<DeviceResources>(options_, std::move(shaderSource_), tableStorage(options_), window_->handle(), options_.width,
                                             options_.height)),
      flight_(std::move(flight)) {
    if (options_.recordFlight) ensureWritable(*options_.recordFlight);
    if (soak) {
        ensureWritable(options_.soakResults());
        soak_.emplace(std::move(*soak));
    }
    // Every headless run sees the same times; --time-step gives a window (or a headless run) its own step.
    if (options_.timeStep) timer_.setFixedStep(*options_.timeStep);
    else if (options_.headless) timer_.setFixedStep(1.0 / 60.0);
}

int App::run() {
    // A headless flight renders its whole length at the fixed step (1/60 s, or --time-step's)
    // unless --frames says otherwise; a held clock (--time-step 0) renders --frames' default.
    const double step = options_.timeStep.value_or(1.0 / 60.0);
    const int frames = flight_ && options_.headless && !options_.frames && !soak_ && step > 0.0
                           ? static_cast<int>(std::ceil(flight_->duration() / step - 1e-9)) + 1
                           : options_.frameCount();
    if (flight_) log::info("playing " + flight_->describe());
    renderFrames(frames);
    if (options_.capture && frames == 0) {  // a windowed run closed by the person: capture the last frame
        renderFrame(options_.captureUi);
        captureFrame();
    }
    if (options_.recordFlight) {
        if (recording_.size() == 0 || timer_.totalSeconds() > recording_.duration() + 0.001)
            recording_.add(timer_.totalSeconds(), state_.camera, state_.sun);  // where the flight ended
        recording_.save(*options_.recordFlight);
        log::info(recording_.describe() + " written to " + options_.recordFlight->string());
    }
    printTimings();
    return soak_ ? soak_->finish(options_.soakResults()) : 0;
}

void App::renderFrames(int frames) {
    for (int frame = 0; frames == 0 || frame < frames; ++frame) {
        if (!window_->processMessages()) break;
        if (window_->minimized()) {
            sleepWhileMinimized();
            --frame;
            continue;
        }
        followWindowSize();
        if (soak_) soak_->beforeFrame(frame, state_);
        timer_.tick();
        update();
        const bool last = frames != 0 && frame + 1 == frames;
        const bool capture = last && options_.capture;
        const bool flightCapture = options_.capture && !dueCaptures_.empty();
        const bool shot = std::exchange(shotRequested_, false);
        // A device lost mid-frame makes some call fail (an Error); one lost by the time of
        // Present says so there. Headless frames have no Present: the device is asked.
        std::string lost;
        try {
            renderFrame((!capture && !flightCapture && !shot) || options_.captureUi);
            if (options_.capture)
                for (const std::string& name : dueCaptures_) captureFrame(name);
            if (capture) captureFrame();
            if (shot) captureShot();
            if (gpu_->swapChain) lost = gpu_->swapChain->present(state_.display.vsync);
        } catch (const Error& e) {
            lost = gpu_->device.removedReason();
            if (lost.empty()) throw;
            lost += std::string(", in the middle of the frame: ") + e.what();
        }
        if (lost.empty()) lost = gpu_->device.removedReason();
        if (lost.empty() && options_.simulateDeviceLoss && frame + 1 == *options_.simulateDeviceLoss)
            lost = "DXGI_ERROR_DEVICE_REMOVED, simulated by --simulate-device-loss";
        if (!lost.empty()) recoverFromDeviceLoss(lost);
        if (soak_) soak_->afterFrame(frame, gpu_->device);
    }
}

void App::sleepWhileMinimized() {
    gpu_->device.waitForGpu();  // the last frame's work is done before the minimized time is counted
    const auto start = std::chrono::steady_clock::now();
    const double cpuAtStart = processCpuSeconds();
    log::info("window minimized after frame " + std::to_string(timer_.frameCount()) + ": drawing nothing until it is restored");
    // Nothing is drawn: the thread sleeps until a message comes, and again after each one that
    // leaves the window minimized (the messages first: a restore is one of them).
    while (window_->processMessages() && window_->minimized()) WaitMessage();
    const double seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
    const double cpu = processCpuSeconds() - cpuAtStart;
    char text[96];
    if (cpuAtStart >= 0.0) std::snprintf(text, sizeof text, "%.1f s minimized, using %.2f s of CPU time", seconds, cpu);
    else std::snprintf(text, sizeof text, "%.1f s minimized (the system did not say how much CPU time it used)", seconds);
    log::info("window restored after " + std::string(text) + "; frame " + std::to_string(timer_.frameCount() + 1) + " is next");
}

void App::followWindowSize() {
    if (!gpu_->swapChain) return;
    if (window_->clientWidth() <= 0 || window_->clientHeight() <= 0) return;  // no area: the last size stays
    const int width = std::clamp(window_->clientWidth(), kMinFrameSide, kMaxFrameSide);
    const int height = std::clamp(window_->clientHeight(), kMinFrameSide, kMaxFrameSide);
    if (width == gpu_->renderer.targets().width() && height == gpu_->renderer.targets().height()) return;
    gpu_->swapChain->resize(width, height);
    gpu_->renderer.resize(width, height, false, gpu_->hdrPrecision);
    log::info("window: " + std::to_string(window_->clientWidth()) + "x" + std::to_string(window_->clientHeight()) + ", frames at " +
              std::to_string(width) + "x" + std::to_string(height));
}

void App::update() {
    gpu_->shaders.beginFrame();  // in use from here on; background compiles swap in
    const double now = timer_.totalSeconds();
    const float dt = static_cast<float>(timer_.deltaSeconds());
    frameTimes_.add(dt * 1000.0f);
    const auto wallClock = std::chrono::steady_clock::now();
    if (state_.shaders.autoReload && gpu_->shaders.hotReloadEnabled() && wallClock - lastSourcePoll_ >= kSourcePollInterval) {
        lastSourcePoll_ = wallClock;
        const ReloadResult result = gpu_->shaders.reloadChanged();
        if (result.attempted())
            setNotice(result.failedTechniques.empty() ? "shaders reloaded after a file change" : "shader reload failed: see the error window",
                      !result.failedTechniques.empty());
    }
    FlightInput input = keyboardMouse_.takeFrameInput(state_.flight);
    input += hidDevices_.poll(now, state_.devices);
    input += xinputPads_.poll(now, state_.devices);
    dueCaptures_.clear();
    if (flight_ && !flightDone_) {
        // The recorded path drives, and input waits for its end. The frame at or past the end shows
        // the last keyframe exactly: a one-keyframe flight is a still view.
        // A soak flies it in a loop. The flight's clock starts at its first frame, which shows
        // time zero (a fixed step's clock has already advanced one step by then).
        if (flightShown_ < 0.0) flightStart_ = now;
        const double flightTime = now - flightStart_;
        const bool loop = soak_ && flight_->duration() > 0.0;
        const Bookmark view = flight_->at(loop ? std::fmod(flightTime, flight_->duration()) : flightTime);
        state_.camera = view.camera;
        state_.sun = view.sun;
        flightDone_ = !loop && flightTime >= flight_->duration();
        // (A microsecond's tolerance: the fixed steps add up to a keyframe's time only to rounding.)
        constexpr double kTolerance = 1e-6;
        if (!loop) dueCaptures_ = flight_->capturesBetween(flightShown_ + kTolerance, flightTime + kTolerance);
        flightShown_ = flightTime;
    } else {
        fly(state_.camera, state_.sun, state_.flight, input, dt);
        if (state_.atmosphere.animateSun) animateSun(state_.sun, dt);
    }
    keepCameraAboveGround();
    constexpr double kRecordPeriodSeconds = 0.1;
    if (options_.recordFlight && (recording_.size() == 0 || now >= recording_.duration() + kRecordPeriodSeconds))
        recording_.add(now, state_.camera, state_.sun);
}

// Yusov 2013's sample keeps the camera at least 100 m above the terrain (terrain.cameraClearance).
void App::keepCameraAboveGround() {
    if (!state_.terrain.enabled || state_.terrain.cameraClearance <= 0.0f) return;
    const glm::dvec3 p = state_.camera.position;
    const double lowest = gpu_->renderer.groundY(p.x, p.z) + state_.terrain.cameraClearance;
    if (p.y < lowest) state_.camera.position.y = static_cast<float>(lowest);
}

void App::recoverFromDeviceLoss(const std::string& why) {
    const auto start = std::chrono::steady_clock::now();
    const int width = gpu_->renderer.targets().width();
    const int height = gpu_->renderer.targets().height();
    log::warning("the Direct3D device was lost after frame " + std::to_string(timer_.frameCount()) + " (" + why +
                 "): making every GPU resource again; the settings and the camera are kept");
    gpu_.reset();  // the old device's objects go first, the GUI's context with them
    gpu_ = std::make_unique<DeviceResources>(options_, openShaderFolder(options_), tableStorage(options_), window_->handle(), width, height);
    ++deviceLosses_;
    const double seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
    char text[64];
    std::snprintf(text, sizeof text, "%.2f s", seconds);
    log::info("device recreated in " + std::string(text) + " (loss " + std::to_string(deviceLosses_) + "); rendering goes on");
    setNotice("the Direct3D device was lost (" + why + ") and made again", true);
}

}  // namespace firmament
