// For tests/gpu/ShadowTest.cpp: a known occluder drawn into the cascades, and the sun's
// visibility from the cascades at points the test chooses.
//   occluder_vs: a horizontal square, square = (x min, z min, x max, z max) at y = height.x,
//                through the cascade's ShadowCasterConstants (b5).
//   visibility:  q.a = (world xyz, view depth), q.b = (normal xyz) -> (visibility, cascade, 0, 0)
#include "shadows/shadow_structures.hlsli"

cbuffer ShadowBuffer : register(b0) { ShadowConstants shadows; };
cbuffer OccluderBuffer : register(b1) {
    float4 square;
    float4 height;
};
cbuffer ShadowCasterBuffer : register(b5) { ShadowCasterConstants caster; };

struct Query {
    float4 a, b;
};
StructuredBuffer<Query> queries : register(t0);
Texture2D<float> shadowMap : register(t1);
SamplerComparisonState shadowComparison : register(s0);
RWStructuredBuffer<float4> results : register(u0);

#include "shadows/cascade_sampling.hlsli"

float4 occluder_vs(uint id : SV_VertexID) : SV_Position {
    static const float2 kCorners[6] = {float2(0, 0), float2(0, 1), float2(1, 0), float2(1, 0), float2(0, 1), float2(1, 1)};
    float2 xz = lerp(square.xy, square.zw, kCorners[id]);
    return mul(caster.worldToClip, float4(xz.x, height.x, xz.y, 1.0));
}

[numthreads(64, 1, 1)]
void visibility(uint3 id : SV_DispatchThreadID) {
    Query q = queries[id.x];
    int cascade;
    float v = sunVisibility(q.a.xyz, q.b.xyz, q.a.w, cascade);
    results[id.x] = float4(v, (float)cascade, 0.0, 0.0);
}
