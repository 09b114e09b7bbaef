// The program's captures (App.h): --capture's and a flight's frames, F12's shots, and batches
// of views (--batch FILE, and --batch - served from standard input), each view from a fresh
// start.
#include "app/App.h"

#include "app/Capture.h"
#include "core/Error.h"
#include "core/FileIO.h"
#include "core/Log.h"
#include "core/SettingsJson.h"
#include "gpu/Readback.h"

#include <chrono>
#include <cstdio>
#include <iostream>
#include <string>

namespace firmament {

ID3D11Texture2D* App::outputTexture() const {
    return gpu_->swapChain ? gpu_->swapChain->backBuffer() : gpu_->renderer.targets().output().texture.Get();
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
    gpu_->renderer.resize(view.width, view.height, true, gpu_->hdrPrecision);
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

}  // namespace firmament
