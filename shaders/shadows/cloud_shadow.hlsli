#ifndef FIRMAMENT_SHADOWS_CLOUD_SHADOW_HLSLI
#define FIRMAMENT_SHADOWS_CLOUD_SHADOW_HLSLI
// Reading the clouds' light-space transparency maps (Yusov 2014, "Integration with light
// scattering"; docs/clouds.md, "Shadows and shafts from clouds"): how much of the sun's light
// the clouds let through to a point. A texel holds (far, -near, 0, T): the clouds' transmittance
// T along the sun's ray through it, and the stretch [far, near] of that ray the clouds occupy,
// as distances toward the sun from its map's centre. A point nearer the sun than the stretch is
// unshadowed, one beyond it gets T, one inside it what the part of the stretch between it and the
// sun lets through, the density taken as uniform along the stretch:
//   T(p) = T ^ saturate((near - h(p)) / (near - far)).
// The four texels around the point are each evaluated so, then blended bilinearly. The near map
// (slice 0) gives way to the far one (slice 1) over its outer rim, and the far one to no shadow
// over its own. The includer declares the cbuffer `cloudShadow` (CloudShadowConstants) and the
// Texture2DArray<float4> `cloudShadowMap`; the passes that write the maps define
// FIRMAMENT_CLOUD_SHADOW_WRITER and get only their geometry.
#include "shadows/shadow_structures.hlsli"

// Map `slice`'s centre (xyz) and half-width (w).
float4 cloudShadowFrame(uint slice) { return slice == 0 ? cloudShadow.centre : cloudShadow.farCentre; }

// Distance toward the sun from map `slice`'s centre.
float cloudShadowHeightIn(uint slice, float3 world) { return dot(world - cloudShadowFrame(slice).xyz, cloudShadow.sun.xyz); }

// The point's place in map `slice`: -1..1 along its x and y axes.
float2 cloudShadowPositionIn(uint slice, float3 world) {
    float4 frame = cloudShadowFrame(slice);
    float3 offset = world - frame.xyz;
    return float2(dot(offset, cloudShadow.right.xyz), dot(offset, cloudShadow.up.xyz)) / frame.w;
}

// The texel of map position p (-1..1), as rasterization numbers them (y down), unclamped.
float2 cloudShadowTexel(float2 p) { return float2(p.x * 0.5 + 0.5, 0.5 - p.y * 0.5) * cloudShadow.right.w; }

#ifndef FIRMAMENT_CLOUD_SHADOW_WRITER
// One texel's transmittance for a point at height h toward the sun.
float cloudTexelTransmittance(float4 texel, float h) {
    if (texel.a >= 1.0) return 1.0;  // no cloud on this ray (the stretch is then empty)
    float nearEnd = -texel.g, farEnd = texel.r;
    float share = saturate((nearEnd - h) / max(nearEnd - farEnd, 1.0e-3));
    return share <= 0.0 ? 1.0 : pow(max(texel.a, 1.0e-12), share);
}

// Map `slice`'s transmittance at `world`, bilinear over the four texels around it; `edge`: how far
// out the point lies (max |x|, |y| of its place; >= 1 outside, where the result is 1).
float cloudSliceTransmittance(uint slice, float3 world, out float edge) {
    float2 p = cloudShadowPositionIn(slice, world);
    edge = max(abs(p.x), abs(p.y));
    if (edge >= 1.0) return 1.0;
    int n = int(cloudShadow.right.w);
    float2 texel = cloudShadowTexel(p) - 0.5;
    float2 base = floor(texel), f = texel - base;
    int2 i0 = clamp(int2(base), 0, n - 1), i1 = clamp(int2(base) + 1, 0, n - 1);
    float h = cloudShadowHeightIn(slice, world);
    float t00 = cloudTexelTransmittance(cloudShadowMap.Load(int4(i0.x, i0.y, slice, 0)), h);
    float t10 = cloudTexelTransmittance(cloudShadowMap.Load(int4(i1.x, i0.y, slice, 0)), h);
    float t01 = cloudTexelTransmittance(cloudShadowMap.Load(int4(i0.x, i1.y, slice, 0)), h);
    float t11 = cloudTexelTransmittance(cloudShadowMap.Load(int4(i1.x, i1.y, slice, 0)), h);
    return lerp(lerp(t00, t10, f.x), lerp(t01, t11, f.x), f.y);
}

// How far into a map's rim a point at `edge` lies: 0 inside the rim, 1 at the map's border.
float cloudShadowRim(float edge) { return saturate((edge - (1.0 - cloudShadow.sun.w)) / cloudShadow.sun.w); }

// The share of the sun's light that the clouds let reach `world` (1 without cloud shadows).
float cloudTransmittance(float3 world) {
    if (cloudShadow.up.w == 0.0) return 1.0;
    float nearEdge, farEdge;
    float nearMap = cloudSliceTransmittance(0, world, nearEdge);
    float rim = cloudShadowRim(nearEdge);
    if (rim <= 0.0) return nearMap;
    float farMap = lerp(cloudSliceTransmittance(1, world, farEdge), 1.0, cloudShadowRim(farEdge));
    return lerp(nearMap, farMap, rim);
}
#endif

#endif
