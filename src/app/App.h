#pragma once
// The program: window, device, swap chain (or an off-screen target when headless), the
// frame targets, input, and the passes run in frame order. Owns nothing a technique can own.
#include "app/CommandLine.h"
#include "app/FlightPath.h"
#include "app/State.h"
#include "app/StepTimer.h"
#include "app/Window.h"
#include "atmosphere/Atmosphere.h"
#include "gpu/ConstantBuffer.h"
#include "gpu/Device.h"
#include "gpu/GpuProfiler.h"
#include "gpu/ShaderLibrary.h"
#include "gpu/SharedStructures.h"
#include "gpu/SwapChain.h"
#include "gpu/Texture.h"
#include "input/HidDevices.h"
#include "input/KeyboardMouse.h"
#include "input/XInputPads.h"
#include "postfx/ToneMapping.h"
#include "scene/OrientationGridPass.h"
#include "shadows/CascadedShadowMaps.h"
#include "terrain/Terrain.h"
#include "ui/FrameTimeHistory.h"
#include "ui/Overlay.h"

#include <memory>

namespace firmament {

class App {
public:
    // `flight`: a camera path to play back first (--flight).
    App(const Options& options, const State& state, std::optional<FlightPath> flight);  // throws Error
    int run();                                         // returns the exit code

private:
    void createFrameTargets(int width, int height);
    void update();
    void renderFrame(bool drawGui);
    void captureFrame();
    void renderTerrain(ID3D11DeviceContext* context);
    void keepCameraAboveGround();
    void printTimings();
    void onKey(WPARAM key);
    void onInput(UINT message, WPARAM wParam, LPARAM lParam);
    void handleRequests(const GuiRequests& requests);
    void reloadShaders();
    void saveState();
    void loadState();
    void setNotice(std::string text, bool isError);
    gpu::FrameConstants frameConstants() const;
    ID3D11RenderTargetView* outputTarget() const;
    ID3D11Texture2D* outputTexture() const;

    Options options_;
    State state_;
    std::unique_ptr<ShaderCompiler> shaderSource_;  // handed to shaders_ once the device exists
    std::unique_ptr<Window> window_;
    Device device_;
    std::unique_ptr<SwapChain> swapChain_;  // null when headless
    ShaderLibrary shaders_;
    GpuProfiler profiler_;
    ConstantBuffer<gpu::FrameConstants> frameConstantBuffer_;
    OrientationGridPass orientationGrid_;
    Atmosphere atmosphere_;
    Terrain terrain_;
    CascadedShadowMaps shadows_;
    ToneMapping toneMapping_;
    std::unique_ptr<Overlay> overlay_;

    KeyboardMouse keyboardMouse_;
    HidDevices hidDevices_;
    XInputPads xinputPads_;

    // Frame targets: HDR radiance (RGBA16F) with depth; headless runs also own the 8-bit
    // output target that the swap chain's back buffer is otherwise.
    Texture2D hdrFrame_;
    Texture2D depth_;
    Texture2D offscreenOutput_;
    int width_ = 0;
    int height_ = 0;

    std::optional<FlightPath> flight_;
    FlightPath recording_;
    StepTimer timer_;
    FrameTimeHistory frameTimes_;
    double lastSourcePoll_ = 0.0;
    std::string notice_;
    bool noticeIsError_ = false;
};

}  // namespace firmament
