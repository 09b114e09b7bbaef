// Pre-computation, step 2: single scattering into the 4D table packed into a 3D texture
// (document 000, "Computing single scattering"). One thread per texel: its world parameters
// from the inverse parameterization, then the integral along the view ray to the top of the
// atmosphere or the ground. Run in slabs of z (PrecomputeSliceConstants) so that no dispatch
// holds the device for long.
#include "atmosphere/single_scattering.hlsli"

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
    ScatteringSample s = texelToWorld(atmosphere, texel);
    float3 start = float3(0.0, atmosphere.earth.x + s.altitude, 0.0);
    float sinView = sqrt(saturate(1.0 - s.cosView * s.cosView));
    float3 viewDir = float3(sinView, s.cosView, 0.0);
    // The sun: cosine cosSun with the zenith, cosSunView with the view direction.
    float sunX = sinView > 1e-6 ? (s.cosSunView - s.cosView * s.cosSun) / sinView : 0.0;
    float3 sunDir = float3(sunX, s.cosSun, sqrt(saturate(1.0 - sunX * sunX - s.cosSun * s.cosSun)));
    bool belowHorizon = texel.y < (uint)n.y / 2;  // the lower half of the view zenith axis
    float rayLength = rayLengthInAtmosphere(atmosphere, start, viewDir, belowHorizon);
    float3 radiance = integrateSingleScattering(atmosphere, netDensityLut, linearClamp, start, viewDir, sunDir, rayLength,
                                                kIntegrationSteps);
    singleScattering[texel] = float4(radiance, 0.0);
}
