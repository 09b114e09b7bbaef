#include "app/App.h"

#include "app/BenchmarkRunner.h"
#include "app/Capture.h"
#include "app/ProcessCounters.h"
#include "atmosphere/SunAnimation.h"
#include "core/Error.h"
#include "core/FileIO.h"
#include "core/Log.h"
#include "core/SettingsJson.h"
#include "gpu/PrecompiledShaders.h"
#include "gpu/SourceShaderCompilers.h"
#include "FirmamentVersion.h"

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <cstring>
#include <iostream>
#include <utility>

namespace firmament {

namespace {

// Shader files are checked four times a second of wall-clock time (not the frame clock, which
// --time-step 0 holds still).
constexpr auto kSourcePollInterval = std::chrono::milliseconds(250);

std::filesystem::path executableFolder() {
    wchar_t path[MAX_PATH];
    const DWORD length = GetModuleFileNameW(nullptr, path, MAX_PATH);
    return std::filesystem::path(std::wstring(path, length)).parent_path();
}

// Checked before any window or device exists, so that bad input fails fast.
std::unique_ptr<ShaderCompiler> openShaderFolder(const Options& options) {
    const auto folder = options.shaderDir.value_or(executableFolder() / "shaders");
    auto shaders = std::make_unique<PrecompiledShaders>(folder);
    log::info("shaders: " + std::to_string(shaders->size()) + " precompiled permutations in " + folder.string());
    return shaders;
}

const Options& checkedOptions(const Options& options) {
    if (options.capture) {
        ensureWritable(options.capturePng());
        ensureWritable(options.captureExr());
    }
    return options;
}

// The cache of the pre-computed tables: --cache-dir, else %LOCALAPPDATA%\Firmament\cache,
// else a "cache" folder beside the program.
TableStorage tableStorage(const Options& options) {
    TableStorage storage;
    storage.exportFolder = options.exportLuts;
    storage.mediaFolder = executableFolder() / "media";
    if (options.noCache) return storage;
    if (options.cacheDir) {
        storage.cacheFolder = options.cacheDir;
    } else if (const wchar_t* localAppData = _wgetenv(L"LOCALAPPDATA"); localAppData && *localAppData) {
        storage.cacheFolder = std::filesystem::path(localAppData) / "Firmament" / "cache";
    } else {
        storage.cacheFolder = executableFolder() / "cache";
    }
    return storage;
}

DeviceOptions deviceOptions(const Options& options) {
    DeviceOptions d;
    d.driver = options.driver;
    d.adapterIndex = options.adapter;
    return d;
}

std::optional<int> digitKey(WPARAM key) {
    if (key >= '1' && key <= '9') return static_cast<int>(key - '0');
    if (key >= VK_NUMPAD1 && key <= VK_NUMPAD9) return static_cast<int>(key - VK_NUMPAD0);
    return std::nullopt;
}

}  // namespace

DeviceResources::DeviceResources(const Options& options, std::unique_ptr<ShaderCompiler> precompiled, const TableStorage& storage,
                                 HWND window, int width, int height)
    : device(deviceOptions(options)),
      shaders(device.device(), std::move(precompiled)),
      renderer(device.device(), device.context(), shaders, storage) {
    log::info("device: " + device.describe());

    // Hot reload compiles from the HLSL folder the build used, unless told otherwise.
    const auto& compiled = static_cast<const PrecompiledShaders&>(shaders.compiler());
    const auto sourceRoot = options.shaderSource ? options.shaderSource : compiled.sourceRoot();
    const auto choice = parseSourceCompilerChoice(options.shaderCompiler).value_or(SourceCompilerChoice::Auto);
    std::error_code ec;
    if (choice == SourceCompilerChoice::None) {
        log::info("shader hot reload: off (--shader-compiler none)");
    } else if (!sourceRoot || !std::filesystem::is_directory(*sourceRoot, ec)) {
        if (options.shaderSource) throw Error("--shader-source: '" + options.shaderSource->string() + "' is not a folder");
        log::warning("shader hot reload: off (the HLSL folder " + (sourceRoot ? sourceRoot->string() : std::string("?")) +
                     " is not there; pass --shader-source)");
    } else if (auto compiler = makeSourceCompiler(choice, *sourceRoot, compiled.cacheLauncher())) {
        log::info("shader hot reload: " + compiler->name() + " from " + sourceRoot->string());
        shaders.enableHotReload(std::move(compiler), *sourceRoot);
    } else {
        log::warning("shader hot reload: off (no shader compiler found: d3dcompiler_47.dll or fxc.exe)");
    }

    if (!options.headless) swapChain = std::make_unique<SwapChain>(device, window, width, height);
    overlay = std::make_unique<Overlay>(window, device.device(), device.context());
    renderer.resize(width, height, !swapChain);
}

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

ID3D11RenderTargetView* App::outputTarget() const {
    return gpu_->swapChain ? gpu_->swapChain->backBufferRtv() : gpu_->renderer.targets().output().rtv.Get();
}

ID3D11Texture2D* App::outputTexture() const {
    return gpu_->swapChain ? gpu_->swapChain->backBuffer() : gpu_->renderer.targets().output().texture.Get();
}

void App::setNotice(std::string text, bool isError) {
    notice_ = std::move(text);
    noticeIsError_ = isError;
}

void App::onInput(UINT message, WPARAM wParam, LPARAM lParam) {
    // (No GUI while the device resources are being made: at start-up and after a device loss.)
    const bool gui = gpu_ && gpu_->overlay;
    keyboardMouse_.onMessage(message, wParam, lParam, gui && gpu_->overlay->wantsMouse(), gui && gpu_->overlay->wantsKeyboard());
}

void App::onKey(WPARAM key) {
    if (gpu_ && gpu_->overlay && gpu_->overlay->wantsKeyboard()) return;
    const bool control = GetKeyState(VK_CONTROL) < 0;
    if (const auto slot = digitKey(key)) {
        if (control) {
            state_.storeBookmark(*slot);
            setNotice("bookmark " + std::to_string(*slot) + " stored", false);
        } else if (state_.recallBookmark(*slot)) {
            setNotice("bookmark " + std::to_string(*slot) + " recalled", false);
        } else {
            setNotice("bookmark " + std::to_string(*slot) + " is empty (Ctrl+" + std::to_string(*slot) + " stores one)", true);
        }
        return;
    }
    switch (key) {
        case VK_F1: state_.ui.help = !state_.ui.help; break;
        case VK_F5: saveState(); break;
        case VK_F8: reloadShaders(); break;
        case VK_F9: loadState(); break;
        case VK_F12: shotRequested_ = true; break;
        case VK_ESCAPE: window_->close(); break;
        default: break;
    }
}

void App::reloadShaders() {
    if (!gpu_->shaders.hotReloadEnabled()) {
        setNotice("shader hot reload is off (see the log)", true);
        return;
    }
    const ReloadResult result = gpu_->shaders.reloadAll();
    if (result.failedTechniques.empty())
        setNotice("reloaded " + std::to_string(result.shadersCompiled) + " shaders in " + std::to_string(static_cast<int>(result.milliseconds)) +
                      " ms" + (result.shadersInBackground ? " (" + std::to_string(result.shadersInBackground) + " more in the background)" : ""),
                  false);
    else
        setNotice("shader reload failed for " + std::to_string(result.failedTechniques.size()) + " technique(s): see the error window", true);
}

void App::saveState() {
    try {
        saveStateFile(state_, options_.stateFile);
        setNotice("state saved to " + options_.stateFile.string(), false);
        log::info("state saved to " + options_.stateFile.string());
    } catch (const Error& e) {
        setNotice(e.what(), true);
        log::error(e.what());
    }
}

void App::loadState() {
    try {
        loadStateFile(state_, options_.stateFile);
        setNotice("state loaded from " + options_.stateFile.string(), false);
        log::info("state loaded from " + options_.stateFile.string());
    } catch (const Error& e) {
        setNotice(e.what(), true);  // the state is unchanged
        log::error(e.what());
    }
}

void App::handleRequests(const GuiRequests& requests) {
    if (requests.toggleFullScreen && gpu_->swapChain) window_->toggleFullScreen();
    if (requests.reloadShaders) reloadShaders();
    if (requests.saveState) saveState();
    if (requests.loadState) loadState();
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

void App::captureView(const CaptureItem& view) {
    const auto start = std::chrono::steady_clock::now();
    options_.capture = view.png;
    options_.captureUi = view.captureUi;
    ensureWritable(options_.capturePng());
    ensureWritable(options_.captureExr());
    state_ = view.state;
    timer_ = StepTimer{};
    timer_.setFixedStep(options_.timeStep.value_or(1.0 / 60.0));  // a headless run's clock (App::App)
    frameTimes_ = FrameTimeHistory{};
    lastSourcePoll_ = {};
    notice_.clear();
    noticeIsError_ = false;
    gpu_->renderer.startOver();
    gpu_->renderer.resize(view.width, view.height, true);
    renderFrames(view.frames);
    const double seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
    char text[32];
    std::snprintf(text, sizeof text, "%.2f s", seconds);
    log::info("batch: " + view.id + ": " + std::to_string(view.frames) + " frame" + (view.frames == 1 ? "" : "s") + " at " +
              std::to_string(view.width) + "x" + std::to_string(view.height) + " in " + text);
}

int App::runBatch(const std::vector<CaptureItem>& views) {
    log::info("batch: " + std::to_string(views.size()) + " views, each from a fresh start");
    for (const CaptureItem& view : views) captureView(view);
    return 0;
}

int App::serveCaptures(const CaptureDefaults& defaults) {
    log::info("batch: reading views from standard input, one a line, until it ends");
    std::string line;
    while (std::getline(std::cin, line)) {
        if (!line.empty() && line.back() == '\r') line.pop_back();
        if (line.empty()) continue;
        CaptureItem view;
        try {
            view = parseCaptureRequest(line, defaults);
            ensureWritable(view.png);
            ensureWritable(std::filesystem::path(view.png).replace_extension(".exr"));
        } catch (const Error& e) {  // bad input: answered, and the next request is read
            log::error(e.what());
            std::printf("batch: refused %s: %s\n", captureRequestId(line).c_str(), e.what());
            std::fflush(stdout);
            continue;
        }
        captureView(view);
        std::printf("batch: done %s\n", view.id.c_str());
        std::fflush(stdout);
    }
    return 0;
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
    gpu_->renderer.resize(width, height, false);
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

// The GUI is built first (its edits apply to this frame), then the renderer draws the frame in
// its order with the GUI as the last pass.
void App::renderFrame(bool drawGui) {
    ID3D11DeviceContext* context = gpu_->device.context();
    const RendererStatus status = gpu_->renderer.status(state_);
    std::vector<std::string> devices = hidDevices_.connectedNames();
    for (int i = 0; i < xinputPads_.connectedCount(); ++i) devices.push_back("Xbox pad (XInput)");
    const FrameTargets& targets = gpu_->renderer.targets();
    GuiModel model{state_,
                   FrameStats{timer_.deltaSeconds() * 1000.0, timer_.framesPerSecond(), targets.width(), targets.height(), gpu_->device.adapterName()},
                   gpu_->renderer.profiler().timings(),
                   frameTimes_,
                   gpu_->shaders.errors(),
                   gpu_->shaders.sourceCompiler() ? gpu_->shaders.sourceCompiler()->name() : std::string(),
                   std::move(devices),
                   notice_,
                   noticeIsError_,
                   status.exposure,
                   status.atmosphereProgress,
                   status.cloudTableProgress,
                   status.cloudBlending};
    const GuiRequests requests = gpu_->overlay->build(model);
    const auto gui = [&](ID3D11RenderTargetView* output) { gpu_->overlay->render(context, output); };
    gpu_->renderer.render(state_, FrameTime{timer_.totalSeconds(), timer_.deltaSeconds()}, options_.headless, outputTarget(),
                     drawGui ? std::function<void(ID3D11RenderTargetView*)>(gui) : nullptr);
    handleRequests(requests);
}

void App::captureFrame(const std::string& name) {
    ID3D11Device* device = gpu_->device.device();
    ID3D11DeviceContext* context = gpu_->device.context();
    const FrameTargets& targets = gpu_->renderer.targets();
    CaptureDescription d;
    const Camera camera = gpu_->renderer.viewCamera(state_);
    d.view = camera.view();
    d.projection = camera.projection(static_cast<float>(targets.width()) / static_cast<float>(targets.height()));
    d.directionToSun = state_.sun.direction();
    d.settings = stateToJson(state_).dump(2);
    d.adapter = gpu_->device.describe();
    d.implementation = implementationId(gpu_->device.implementation());
    d.frame = static_cast<int>(timer_.frameCount());
    d.techniques = gpu_->renderer.captureAttributes(state_);
    writeCapture(options_.capturePng(name), options_.captureExr(name), readTexture2D(device, context, outputTexture()),
                 readTexture2D(device, context, targets.hdr().texture.Get()), d);
    log::info("captured " + options_.capturePng(name).string() + " and " + options_.captureExr(name).string());
}

void App::captureShot() {
    const std::string name = "shot-" + std::to_string(shotsTaken_ + 1);
    try {
        captureFrame(name);
        ++shotsTaken_;
        setNotice("captured " + options_.capturePng(name).string(), false);
    } catch (const Error& e) {
        setNotice(e.what(), true);
        log::error(e.what());
    }
}

int App::runBenchmark(const BenchmarkPlan& plan) {
    ensureWritable(options_.benchmarkResults());
    log::info("benchmark '" + plan.name + "': " + std::to_string(plan.scenarios.size()) + " scenarios, " + std::to_string(plan.warmupFrames) +
              " warm-up and " + std::to_string(plan.measuredFrames) + " measured frames each, on " + gpu_->device.describe());
    const auto scratch = std::filesystem::temp_directory_path() / ("firmament-benchmark-" + std::to_string(GetCurrentProcessId()));
    const BenchmarkRun run = firmament::runBenchmark(gpu_->renderer, gpu_->device.context(), plan, scratch);
    std::error_code ec;
    std::filesystem::remove_all(scratch, ec);
    const BenchmarkInfo info{kFirmamentVersion, gpu_->device.describe(), implementationId(gpu_->device.implementation()),
                             options_.benchmark ? options_.benchmark->string() : std::string()};
    const std::string text = benchmarkReport(plan, run.results, run.tables, info).dump(2) + "\n";
    writeFileText(options_.benchmarkResults(), text);
    std::fputs(benchmarkTable(plan, run.results, run.tables).c_str(), stdout);
    std::printf("\nbenchmark results written to %s\n", options_.benchmarkResults().string().c_str());
    std::fflush(stdout);
    return 0;
}

void App::printTimings() {
    GpuProfiler& profiler = gpu_->renderer.profiler();
    profiler.flush();
    std::printf("GPU time per pass over %llu frames at %dx%d on %s:\n", static_cast<unsigned long long>(timer_.frameCount()),
                gpu_->renderer.targets().width(), gpu_->renderer.targets().height(), gpu_->device.describe().c_str());
    std::printf("  %-24s %10s %10s %10s\n", "pass", "mean ms", "min ms", "max ms");
    for (const PassTiming& t : profiler.timings())
        std::printf("  %-24s %10.3f %10.3f %10.3f\n", t.name.c_str(), t.meanMs, t.minMs, t.maxMs);
    if (deviceLosses_ > 0)
        std::printf("  (the device was lost %d time%s: these are the frames since it was last made again)\n", deviceLosses_,
                    deviceLosses_ == 1 ? "" : "s");
    if (profiler.disjointFrames())
        std::printf("  (%llu frames had unreliable timestamps and were left out)\n", static_cast<unsigned long long>(profiler.disjointFrames()));
    std::fflush(stdout);
}

}  // namespace firmament
