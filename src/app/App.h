#pragma once
// The program: window, device, swap chain (or an off-screen target when headless), the
// frame targets, and the passes run in frame order. Owns nothing a technique can own.
#include "app/CommandLine.h"
#include "app/StepTimer.h"
#include "app/Window.h"
#include "core/Camera.h"
#include "gpu/Device.h"
#include "gpu/GpuProfiler.h"
#include "gpu/PrecompiledShaders.h"
#include "gpu/ShaderLibrary.h"
#include "gpu/SwapChain.h"
#include "gpu/Texture.h"
#include "postfx/DisplayEncodePass.h"
#include "ui/Overlay.h"

#include <memory>

namespace firmament {

class App {
public:
    explicit App(const Options& options);  // throws Error
    int run();                             // returns the exit code

private:
    void createFrameTargets(int width, int height);
    void renderFrame();
    void captureFrame();
    void printTimings();
    void onKey(WPARAM key);
    std::string settingsText() const;
    ID3D11RenderTargetView* outputTarget() const;
    ID3D11Texture2D* outputTexture() const;

    Options options_;
    std::unique_ptr<ShaderCompiler> shaderSource_;  // handed to shaders_ once the device exists
    std::unique_ptr<Window> window_;
    Device device_;
    std::unique_ptr<SwapChain> swapChain_;  // null when headless
    ShaderLibrary shaders_;
    GpuProfiler profiler_;
    DisplayEncodePass displayEncode_;
    std::unique_ptr<Overlay> overlay_;

    // Frame targets: HDR radiance (RGBA16F) with depth; headless runs also own the 8-bit
    // output target that the swap chain's back buffer is otherwise.
    Texture2D hdrFrame_;
    Texture2D depth_;
    Texture2D offscreenOutput_;
    int width_ = 0;
    int height_ = 0;

    StepTimer timer_;
    Camera camera_;
    glm::vec3 directionToSun_;
};

}  // namespace firmament
