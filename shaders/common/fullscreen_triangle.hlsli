#ifndef FIRMAMENT_FULLSCREEN_TRIANGLE_HLSLI
#define FIRMAMENT_FULLSCREEN_TRIANGLE_HLSLI
// One triangle that covers the viewport, from SV_VertexID alone (no vertex buffer):
// vertices (-1,1), (3,1), (-1,-3) in clip space; uv is (0,0) at the top-left pixel corner.

struct FullscreenVertex {
    float4 position : SV_Position;
    float2 uv : TEXCOORD0;
};

FullscreenVertex fullscreenTriangle(uint vertexId) {
    FullscreenVertex v;
    v.uv = float2((vertexId << 1) & 2, vertexId & 2);
    v.position = float4(v.uv * float2(2.0, -2.0) + float2(-1.0, 1.0), 0.0, 1.0);
    return v;
}

#endif
