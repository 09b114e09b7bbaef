#include "app/App.h"

#include "app/Capture.h"
#include "core/Error.h"
#include "core/FileIO.h"
#include "core/Log.h"
#include "FirmamentVersion.h"

#include <cmath>
#include <cstdio>
#include <cstring>
#include <sstream>

namespace firmament {

namespace {

// Until the sky and the terrain draw, the HDR frame holds this clear value (linear radiance).
constexpr float kBackground[4] = {0.02f, 0.025f, 0.035f, 1.0f};

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

DeviceOptions deviceOptions(const Options& options) {
    DeviceOptions d;
    d.driver = options.driver;
    d.adapterIndex = options.adapter;
    return d;
}

}  // namespace

App::App(const Options& options)
    : options_(checkedOptions(options)),
      shaderSource_(openShaderFolder(options_)),
      window_(std::make_unique<Window>(L"Firmament " + std::wstring(kFirmamentVersion, kFirmamentVersion + std::strlen(kFirmamentVersion)),
                                       options_.width, options_.height, !options_.headless,
                                       Window::Callbacks{&Overlay::handleMessage, [this](WPARAM key) { onKey(key); }})),
      device_(deviceOptions(options_)),
      shaders_(device_.device(), std::move(shaderSource_)),
      profiler_(device_.device(), device_.context()),
      displayEncode_(device_.device()),
      directionToSun_(directionFromElevationAzimuth(0.5235988f, 0.0f)) {
    log::info("device: " + device_.describe());
    if (!options_.headless)
        swapChain_ = std::make_unique<SwapChain>(device_, window_->handle(), options_.width, options_.height);
    overlay_ = std::make_unique<Overlay>(window_->handle(), device_.device(), device_.context());
    createFrameTargets(options_.width, options_.height);
    if (options_.headless) timer_.setFixedStep(1.0 / 60.0);  // every headless run sees the same times
}

void App::createFrameTargets(int width, int height) {
    ID3D11Device* device = device_.device();
    hdrFrame_ = createColorTexture(device, width, height, DXGI_FORMAT_R16G16B16A16_FLOAT,
                                   D3D11_BIND_RENDER_TARGET | D3D11_BIND_SHADER_RESOURCE);
    depth_ = createDepthTexture(device, width, height);
    if (!swapChain_)
        offscreenOutput_ = createColorTexture(device, width, height, SwapChain::kFormat, D3D11_BIND_RENDER_TARGET);
    width_ = width;
    height_ = height;
}

ID3D11RenderTargetView* App::outputTarget() const {
    return swapChain_ ? swapChain_->backBufferRtv() : offscreenOutput_.rtv.Get();
}

ID3D11Texture2D* App::outputTexture() const {
    return swapChain_ ? swapChain_->backBuffer() : offscreenOutput_.texture.Get();
}

void App::onKey(WPARAM key) {
    if (overlay_ && overlay_->wantsKeyboard()) return;
    if (key == VK_F1 && overlay_) overlay_->toggleHelp();
    if (key == VK_ESCAPE) window_->close();
}

int App::run() {
    const int frames = options_.frameCount();
    for (int frame = 0; frames == 0 || frame < frames; ++frame) {
        if (!window_->processMessages()) break;
        if (window_->minimized()) {
            WaitMessage();  // nothing to draw: sleep until the window comes back
            --frame;
            continue;
        }
        if (swapChain_ && (window_->clientWidth() != width_ || window_->clientHeight() != height_)) {
            swapChain_->resize(window_->clientWidth(), window_->clientHeight());
            createFrameTargets(swapChain_->width(), swapChain_->height());
        }
        timer_.tick();
        renderFrame();
        const bool last = frames != 0 && frame + 1 == frames;
        if (last && options_.capture) captureFrame();
        if (swapChain_) swapChain_->present(options_.vsync);
    }
    if (options_.capture && frames == 0) {  // a windowed run closed by the person: capture the last frame
        renderFrame();
        captureFrame();
    }
    printTimings();
    return 0;
}

void App::renderFrame() {
    ID3D11DeviceContext* context = device_.context();
    profiler_.beginFrame();
    {
        auto pass = profiler_.scope("Clear frame targets");
        context->ClearRenderTargetView(hdrFrame_.rtv.Get(), kBackground);
        context->ClearDepthStencilView(depth_.dsv.Get(), D3D11_CLEAR_DEPTH, 1.0f, 0);
    }
    {
        auto pass = profiler_.scope("Display encode");
        displayEncode_.render(context, shaders_, hdrFrame_.srv.Get(), outputTarget(), width_, height_);
    }
    FrameStats stats{timer_.deltaSeconds() * 1000.0, timer_.framesPerSecond(), width_, height_, device_.adapterName()};
    overlay_->build(stats, profiler_.timings());
    {
        auto pass = profiler_.scope("GUI");
        overlay_->render(context, outputTarget());
    }
    profiler_.endFrame();
}

std::string App::settingsText() const {
    std::ostringstream s;
    s << "device.driver = " << (options_.adapter ? "adapter" : options_.driver == DriverType::Warp ? "warp" : "hardware") << "\n";
    if (options_.adapter) s << "device.adapter = " << *options_.adapter << "\n";
    s << "display.resolution = " << width_ << "x" << height_ << "\n";
    s << "display.vsync = " << (options_.vsync ? "on" : "off") << "\n";
    s << "display.headless = " << (options_.headless ? "on" : "off") << "\n";
    s << "camera.position = " << camera_.position.x << " " << camera_.position.y << " " << camera_.position.z << "\n";
    s << "camera.yaw = " << camera_.yawRadians << "\n";
    s << "camera.pitch = " << camera_.pitchRadians << "\n";
    s << "camera.verticalFov = " << camera_.verticalFovRadians << "\n";
    s << "sun.direction = " << directionToSun_.x << " " << directionToSun_.y << " " << directionToSun_.z << "\n";
    return s.str();
}

void App::captureFrame() {
    ID3D11Device* device = device_.device();
    ID3D11DeviceContext* context = device_.context();
    CaptureDescription d;
    d.view = camera_.view();
    d.projection = camera_.projection(static_cast<float>(width_) / static_cast<float>(height_));
    d.directionToSun = directionToSun_;
    d.settings = settingsText();
    d.adapter = device_.describe();
    d.frame = static_cast<int>(timer_.frameCount());
    writeCapture(options_.capturePng(), options_.captureExr(), readTexture2D(device, context, outputTexture()),
                 readTexture2D(device, context, hdrFrame_.texture.Get()), d);
    log::info("captured " + options_.capturePng().string() + " and " + options_.captureExr().string());
}

void App::printTimings() {
    profiler_.flush();
    std::printf("GPU time per pass over %llu frames at %dx%d on %s:\n",
                static_cast<unsigned long long>(timer_.frameCount()), width_, height_, device_.describe().c_str());
    std::printf("  %-24s %10s %10s %10s\n", "pass", "mean ms", "min ms", "max ms");
    for (const PassTiming& t : profiler_.timings())
        std::printf("  %-24s %10.3f %10.3f %10.3f\n", t.name.c_str(), t.meanMs, t.minMs, t.maxMs);
    if (profiler_.disjointFrames())
        std::printf("  (%llu frames had unreliable timestamps and were left out)\n",
                    static_cast<unsigned long long>(profiler_.disjointFrames()));
    std::fflush(stdout);
}

}  // namespace firmament
