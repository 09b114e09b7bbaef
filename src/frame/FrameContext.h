#pragma once
// What every pass of a frame needs, handed from the renderer to each technique's update and
// render steps: the device and its context, the shader library, the profiler that times the
// passes, the frame's constants (camera, sun, screen, time: FrameConstants at b0) and targets.
#include "frame/FrameTargets.h"
#include "gpu/GpuProfiler.h"
#include "gpu/ShaderLibrary.h"
#include "gpu/SharedStructures.h"

#include <d3d11.h>

namespace firmament {

struct Camera;
struct Sun;

struct FrameContext {
    ID3D11Device* device;
    ID3D11DeviceContext* context;
    ShaderLibrary& shaders;
    GpuProfiler& profiler;
    FrameTargets& targets;
    ID3D11Buffer* frameConstants;         // FrameConstants, bound at b0 by the passes that read it
    const gpu::FrameConstants& constants;  // the same, on the CPU
    const Camera& camera;
    const Sun& sun;
    double timeSeconds;  // since the start
    double dtSeconds;    // since the last frame
    // Work spread over frames (table pre-computation) is finished within this frame: headless
    // runs, captures and benchmarks see complete tables from their first frame.
    bool finishWorkNow;

    int width() const { return targets.width(); }
    int height() const { return targets.height(); }
};

}  // namespace firmament
