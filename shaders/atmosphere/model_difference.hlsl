// The difference view of two atmosphere models: |second - first|, per colour, for the pixels of
// one part (ps_sky where nothing was drawn, ps_aerial_perspective over geometry), from copies of
// the frame as each model drew it. Tone mapping then shows it.
#include "common/fullscreen_triangle.hlsli"

Texture2D<float4> firstModel : register(t0);
Texture2D<float> sceneDepth : register(t1);
Texture2D<float4> secondModel : register(t2);

FullscreenVertex vs_main(uint vertexId : SV_VertexID) {
    return fullscreenTriangle(vertexId);
}

float4 difference(int2 pixel) {
    return float4(abs(secondModel.Load(int3(pixel, 0)).rgb - firstModel.Load(int3(pixel, 0)).rgb), 1.0);
}

float4 ps_sky(FullscreenVertex input) : SV_Target {
    int2 pixel = int2(input.position.xy);
    if (sceneDepth.Load(int3(pixel, 0)) > 0.0) discard;  // reversed Z: geometry, the other part's
    return difference(pixel);
}

float4 ps_aerial_perspective(FullscreenVertex input) : SV_Target {
    int2 pixel = int2(input.position.xy);
    if (sceneDepth.Load(int3(pixel, 0)) <= 0.0) discard;  // nothing drawn: the sky part's
    return difference(pixel);
}
