#ifndef FIRMAMENT_HILLAIRE_PRECOMPUTE_COMMON_HLSLI
#define FIRMAMENT_HILLAIRE_PRECOMPUTE_COMMON_HLSLI
// What Hillaire 2020's pre-computation passes share: the constants (b0: the atmosphere, b1: the
// model's sizes; src/atmosphere/AtmosphereComputeInputs binds them), the sampler, and the
// scattering coefficient.
#include "atmosphere/hillaire/parameterization.hlsli"
#include "atmosphere/physics.hlsli"

cbuffer AtmosphereBuffer : register(b0) {
    AtmosphereConstants atmosphere;
};
cbuffer HillaireBuffer : register(b1) {
    HillaireConstants hillaire;
};
SamplerState linearClamp : register(s0);

// Rayleigh's and Mie's scattering coefficient (1/m) at altitude h, without their phases.
float3 scatteringAt(float h) {
    float3 d = particleDensity(atmosphere, h);
    return atmosphere.rayleighScattering.rgb * d.x + atmosphere.mieScattering.rgb * d.y;
}

// The unit coordinates of a texel's centre in a table of `size` texels (the inverse of
// x = 0.5 / n + u (1 - 1 / n) at x = (i + 0.5) / n): i / (n - 1).
float2 texelUnit(uint2 texel, float2 size) { return (float2)texel / (size - 1.0); }

#endif
