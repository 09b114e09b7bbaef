#ifndef FIRMAMENT_BRUNETON_PRECOMPUTE_COMMON_HLSLI
#define FIRMAMENT_BRUNETON_PRECOMPUTE_COMMON_HLSLI
// What every pre-computation pass of Bruneton and Neyret's tables shares: the constants, the
// sampler, and integrals along a ray given by (r, mu).
#include "atmosphere/bruneton/lookup.hlsli"

cbuffer AtmosphereBuffer : register(b0) {
    AtmosphereConstants atmosphere;
};
cbuffer BrunetonBuffer : register(b1) {
    BrunetonConstants bruneton;
};
cbuffer SliceBuffer : register(b2) {
    PrecomputeSliceConstants slab;
};
SamplerState linearClamp : register(s0);

// The altitude at distance t along the ray (r, mu): physics.hlsli's altitudeAlongRay.
float altitudeAt(float r, float rho2, float mu, float t) { return altitudeAlongRay(atmosphere, r, rho2, mu, t); }

// Length of the ray (r, mu) to the ground (`toGround`: the texel's half says) or to the top.
float rayLength(float r, float rho2, float mu, bool toGround) {
    return toGround ? distanceToGround(r, mu, rho2) : distanceToTop(atmosphere, r, mu, rho2);
}

// The in-scatter texel this thread computes; false outside the table or the slab of layers.
bool inscatterThread(uint3 id, out uint3 texel, out InscatterSample s) {
    texel = id + uint3(0, 0, slab.range.x);
    float4 n = bruneton.inscatterSize;
    s = (InscatterSample)0;
    if (texel.x >= (uint)(n.z * n.w) || texel.y >= (uint)n.y || texel.z >= slab.range.y) return false;
    s = inscatterTexel(atmosphere, bruneton, texel);
    return true;
}

#endif
