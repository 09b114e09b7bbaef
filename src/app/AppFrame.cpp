// One frame of the program (App.h): the GUI's model (the state, the frame's statistics and
// timings, shader errors, devices, the notice, the renderer's status) built first, so that its
// edits apply to this frame; then the renderer's frame order into the output, the GUI last.
#include "app/App.h"

#include <functional>
#include <string>
#include <utility>
#include <vector>

namespace firmament {

ID3D11RenderTargetView* App::outputTarget() const {
    return gpu_->swapChain ? gpu_->swapChain->backBufferRtv() : gpu_->renderer.targets().output().rtv.Get();
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

}  // namespace firmament
