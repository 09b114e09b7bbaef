// Pre-computation, step 2: single scattering into the 4D table packed into a 3D texture
// (Yusov 2013, "Computing single scattering"). One thread per texel: its world parameters
// from the inverse parameterization, then the integral along the view ray to the top of the
// atmosphere or the ground, S_R into the table's first bank of altitude texels and S_M into its
// second, without their phases (lookup.hlsli, lookUpSpeciesScattering), times kTableScale. Run in slabs of z
// (PrecomputeSliceConstants) so that no dispatch holds the device for long.
#include "atmosphere/yusov/single_scattering.hlsli"

cbuffer AtmosphereBuffer : register(b0) {
    AtmosphereConstants atmosphere;
};
cbuffer SliceBuffer : register(b1) {
    PrecomputeSliceConstants slab;
};

Texture2D<float4> netDensityLut : register(t0);
SamplerState linearClamp : register(s0);
RWTexture3D<float4> singleScattering : register(u0);

static const int kIntegrationSteps = 128;

[numthreads(4, 8, 4)]
void main(uint3 id : SV_DispatchThreadID) {
    uint3 texel = id + uint3(0, 0, slab.range.x);
    float4 n = atmosphere.scatteringLutSize;
    if (texel.x >= (uint)n.x || texel.y >= (uint)n.y || texel.z >= slab.range.y) return;
    TexelRay ray = texelRay(atmosphere, texel);
    float rayLength = rayLengthInAtmosphere(atmosphere, ray.start, ray.viewDir, ray.belowHorizon);
    SpeciesScattering s = integrateSpeciesScattering(atmosphere, netDensityLut, linearClamp, ray.start, ray.viewDir, ray.sunDir, rayLength,
                                                     kIntegrationSteps);
    singleScattering[texel] = float4(s.rayleigh * kTableScale, 0.0);
    singleScattering[texel + uint3((uint)n.x, 0, 0)] = float4(s.mie * kTableScale, 0.0);
}
