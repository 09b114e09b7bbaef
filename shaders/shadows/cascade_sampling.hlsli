#ifndef FIRMAMENT_SHADOWS_CASCADE_SAMPLING_HLSLI
#define FIRMAMENT_SHADOWS_CASCADE_SAMPLING_HLSLI
// Reading the cascaded shadow maps (src/shadows/CascadedShadowMaps.h): which cascade a point
// falls in, and how much of the sun it sees. The includer declares the cbuffer `shadows`
// (ShadowConstants), the Texture2D<float> `shadowMap` (the cascades' atlas) and the
// SamplerComparisonState `shadowComparison` (LESS_EQUAL, bilinear: each tap is a 2x2
// percentage-closer filter).
#include "shadows/shadow_structures.hlsli"

float vectorComponent(float4 v, uint i) { return i == 0 ? v.x : (i == 1 ? v.y : (i == 2 ? v.z : v.w)); }
float cascadeSplit(uint i) { return vectorComponent(shadows.splits[i / 4], i % 4); }
float cascadeTexelWorldSize(uint i) { return vectorComponent(shadows.texelWorldSize[i / 4], i % 4); }

// (u, v, depth) in the cascade's own tile.
float3 shadowMapCoordinates(uint cascade, float3 world) {
    return mul(shadows.worldToShadow[cascade], float4(world, 1.0)).xyz;
}

// From a cascade's tile to the atlas.
float2 atlasCoordinates(uint cascade, float2 uv) {
    return (uv + float2(cascade % 4, cascade / 4)) * shadows.atlas.zw;
}

// Inside the cascade with room for the 5-tap filter's footprint.
bool insideCascade(float3 uvz) {
    float margin = 2.0 * shadows.map.y;
    return all(uvz.xy > margin) && all(uvz.xy < 1.0 - margin) && uvz.z > 0.0 && uvz.z < 1.0;
}

// The cascade that shades `world`, -1 beyond the last. Best cascade search: the smallest
// cascade the point projects into; otherwise the cascade whose depth range holds viewDepth.
int selectCascade(float3 world, float viewDepth) {
    uint count = shadows.mode.x;
    if (shadows.mode.z != 0) {
        for (uint c = 0; c < count; ++c)
            if (insideCascade(shadowMapCoordinates(c, world))) return (int)c;
        return -1;
    }
    for (uint c = 0; c < count; ++c)
        if (viewDepth < cascadeSplit(c + 1)) return insideCascade(shadowMapCoordinates(c, world)) ? (int)c : -1;
    return -1;
}

// Fraction of the sun's disc visible from `world` (1 beyond the shadows' reach). The point is
// pushed along its normal by a few texels of its cascade (normal offset) against acne.
float sunVisibility(float3 world, float3 normal, float viewDepth, out int cascade) {
    cascade = selectCascade(world, viewDepth);
    if (cascade < 0) return 1.0;
    float3 offsetWorld = world + normal * (shadows.map.w * cascadeTexelWorldSize((uint)cascade));
    float3 uvz = shadowMapCoordinates((uint)cascade, offsetWorld);
    float depth = uvz.z - shadows.map.z;
    float2 uv = atlasCoordinates((uint)cascade, uvz.xy);
    float visibility = shadowMap.SampleCmpLevelZero(shadowComparison, uv, depth);
    if (shadows.mode.y != 0) {  // smooth shadows: four more taps a texel away
        float2 t = shadows.map.y * shadows.atlas.zw;
        visibility += shadowMap.SampleCmpLevelZero(shadowComparison, uv + float2(t.x, 0.0), depth);
        visibility += shadowMap.SampleCmpLevelZero(shadowComparison, uv - float2(t.x, 0.0), depth);
        visibility += shadowMap.SampleCmpLevelZero(shadowComparison, uv + float2(0.0, t.y), depth);
        visibility += shadowMap.SampleCmpLevelZero(shadowComparison, uv - float2(0.0, t.y), depth);
        visibility *= 0.2;
    }
    return visibility;
}

// The "show cascades" tint of cascade c.
float3 cascadeTint(int c) {
    static const float3 kTints[8] = {float3(1.0, 0.35, 0.35), float3(0.35, 1.0, 0.35), float3(0.4, 0.5, 1.0), float3(1.0, 1.0, 0.3),
                                     float3(1.0, 0.35, 1.0), float3(0.3, 1.0, 1.0), float3(1.0, 0.65, 0.25), float3(0.8, 0.8, 0.8)};
    return c < 0 ? float3(1.0, 1.0, 1.0) : kTints[c];
}

#endif
