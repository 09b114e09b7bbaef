// Display encode: the HDR frame to the 8-bit back buffer, clamped to [0,1] and sRGB encoded.
// A plain pass-through until tone mapping (exposure and the seven operators) replaces it.
#include "common/fullscreen_triangle.hlsli"
#include "common/srgb.hlsli"

Texture2D<float4> hdrFrame : register(t0);

FullscreenVertex vs_main(uint vertexId : SV_VertexID) {
    return fullscreenTriangle(vertexId);
}

float4 ps_main(FullscreenVertex input) : SV_Target {
    float3 radiance = hdrFrame.Load(int3(input.position.xy, 0)).rgb;
    return float4(linearToSrgb(saturate(radiance)), 1.0);
}
