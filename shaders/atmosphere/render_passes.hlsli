#ifndef FIRMAMENT_ATMOSPHERE_RENDER_PASSES_HLSLI
#define FIRMAMENT_ATMOSPHERE_RENDER_PASSES_HLSLI
// What both models' render passes (yusov/render.hlsl, bruneton/render.hlsl) bind alike: the
// frame's and the atmosphere's constants (b0, b1), the frame before the pass and its depth
// (t0, t1), the sampler every look-up uses (s0), and the full-screen triangle they draw. Each
// model binds its own constants from b2 and its tables from t2.
#include "atmosphere/atmosphere_structures.hlsli"
#include "common/fullscreen_triangle.hlsli"

cbuffer FrameBuffer : register(b0) {
    FrameConstants frame;
};
cbuffer AtmosphereBuffer : register(b1) {
    AtmosphereConstants atmosphere;
};

Texture2D<float4> sceneRadiance : register(t0);  // the HDR frame before the pass (ps_aerial_perspective)
Texture2D<float> sceneDepth : register(t1);
SamplerState linearClamp : register(s0);

FullscreenVertex vs_main(uint vertexId : SV_VertexID) {
    return fullscreenTriangle(vertexId);
}

#endif
