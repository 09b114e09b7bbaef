// Scene luminance, step 3 of 3: temporal light adaptation. The adapted value, ln of the
// luminance the eye is adapted to, moves towards this frame's measured ln(log-average
// luminance) (by either metering: average_downsample.hlsl or luminance_histogram.hlsl) by the weight 1 - exp(-dt / tau) computed on the CPU: an exponential approach
// with time constant tau, whatever the frame rate. A weight of 1 takes the measured value
// (adaptation off, or the first frame).
#include "common/fullscreen_triangle.hlsli"
#include "postfx/postfx_structures.hlsli"

cbuffer SceneLuminanceBuffer : register(b0) {
    SceneLuminanceConstants sceneLuminance;
};

Texture2D<float> measuredLog : register(t0);      // 1 x 1, this frame's metered value (either metering)
Texture2D<float> previousAdapted : register(t1);  // 1 x 1, last frame's result

FullscreenVertex vs_main(uint vertexId : SV_VertexID) {
    return fullscreenTriangle(vertexId);
}

float ps_main(FullscreenVertex input) : SV_Target {
    float measured = measuredLog.Load(int3(0, 0, 0));
    float weight = sceneLuminance.adaptation.x;
    if (weight >= 1.0) return measured;  // the previous value may be undefined: never read it then
    float previous = previousAdapted.Load(int3(0, 0, 0));
    return previous + (measured - previous) * weight;
}
