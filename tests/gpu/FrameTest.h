#pragma once
// GPU test fixture for tests that run a technique's passes the way the renderer does: the WARP
// device, with the frame's constant buffer, a timestamp profiler and frame targets.
#include "WarpDevice.h"
#include "core/Camera.h"
#include "frame/FrameContext.h"
#include "frame/FrameTargets.h"
#include "gpu/ConstantBuffer.h"
#include "gpu/GpuProfiler.h"
#include "gpu/SharedStructures.h"

#include <memory>

namespace firmament::test {

class FrameTest : public WarpDevice {
protected:
    // Call from SetUp(): the targets are width x height.
    void setUpFrame(int width, int height) {
        frameConstants = std::make_unique<ConstantBuffer<gpu::FrameConstants>>(device());
        profiler = std::make_unique<GpuProfiler>(device(), context());
        targets.resize(device(), width, height, true);
    }

    // A frame context over these targets whose work finishes at once.
    FrameContext frameContext(const gpu::FrameConstants& constants, const Camera& camera, const Sun& sun) {
        return {device(), context(), *productShaderLibrary, *profiler, targets, frameConstants->get(), constants, camera, sun, 0.0, 1.0 / 60.0, true};
    }

    std::unique_ptr<ConstantBuffer<gpu::FrameConstants>> frameConstants;
    std::unique_ptr<GpuProfiler> profiler;
    FrameTargets targets;
};

}  // namespace firmament::test
