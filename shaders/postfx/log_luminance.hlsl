// Scene luminance, step 1 of 3: the HDR frame into a 64 x 64 target of ln(delta + L), the
// logarithm inside Reinhard et al. 2002's log-average luminance (eq. 1). Each texel averages
// a 4 x 4 grid of pixels spread over its footprint in the frame, so every part of the frame
// counts whatever its size; for a 256 x 256 frame that grid is every pixel exactly.
// Steps 2 (average_downsample.hlsl) and 3 (light_adaptation.hlsl) follow.
#include "common/fullscreen_triangle.hlsli"
#include "postfx/postfx_structures.hlsli"
#include "postfx/tone_mapping_operators.hlsli"

cbuffer SceneLuminanceBuffer : register(b0) {
    SceneLuminanceConstants sceneLuminance;
};

Texture2D<float4> hdrFrame : register(t0);

static const float kLuminanceTargetSize = 64.0;
static const int kSamplesPerAxis = 4;

FullscreenVertex vs_main(uint vertexId : SV_VertexID) {
    return fullscreenTriangle(vertexId);
}

float ps_main(FullscreenVertex input) : SV_Target {
    float2 pixelsPerTexel = sceneLuminance.source.xy / kLuminanceTargetSize;
    float2 footprintCorner = floor(input.position.xy) * pixelsPerTexel;
    float sum = 0.0;
    [unroll] for (int y = 0; y < kSamplesPerAxis; ++y) {
        [unroll] for (int x = 0; x < kSamplesPerAxis; ++x) {
            float2 offset = (float2(x, y) + 0.5) / kSamplesPerAxis;
            int2 pixel = int2(footprintCorner + offset * pixelsPerTexel);
            float3 radiance = clamp(hdrFrame.Load(int3(pixel, 0)).rgb, 0.0, kMaxRadiance);
            sum += log(kLogLuminanceDelta + relativeLuminance(radiance));
        }
    }
    return sum / (kSamplesPerAxis * kSamplesPerAxis);
}
