// Display encode: the HDR frame to the 8-bit back buffer: scaled by the manual exposure,
// clamped to [0,1] and sRGB encoded. Tone mapping (issue: the seven operators and auto
// exposure) takes its place later.
#include "common/fullscreen_triangle.hlsli"
#include "common/shared_structures.hlsli"
#include "common/srgb.hlsli"

cbuffer DisplayEncodeBuffer : register(b0) {
    DisplayEncodeConstants displayEncode;
};

Texture2D<float4> hdrFrame : register(t0);

FullscreenVertex vs_main(uint vertexId : SV_VertexID) {
    return fullscreenTriangle(vertexId);
}

float4 ps_main(FullscreenVertex input) : SV_Target {
    float3 radiance = hdrFrame.Load(int3(input.position.xy, 0)).rgb * displayEncode.exposure.x;
    return float4(linearToSrgb(saturate(radiance)), 1.0);
}
