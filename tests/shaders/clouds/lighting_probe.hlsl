// Probes of the clouds' shading functions (clouds/particle_lighting.hlsli, optical_depth_table.hlsli)
// for tests/gpu/CloudShadingTest.cpp: per probe an entry point s, a direction d into the unit
// sphere and the sun's direction l, an optical radius (s's w), and a depth and thickness of a
// deck (d's and l's w); out, two per probe: the scattering table's single scattering, multiple
// scattering and the forward peak's at them, deck diffusion's multiple scattering at cosine d . l;
// and the optical depth table's mean density along the chord, and the solved slab's multiple
// scattering at cosine d . l.
#include "clouds/optical_depth_table.hlsli"
#include "clouds/particle_shape.hlsli"

cbuffer CloudShadingBuffer : register(b3) { CloudShadingConstants shading; };
Texture3D<float> opticalDepthTable : register(t2);
Texture3D<float4> scatteringTable : register(t4);
StructuredBuffer<float4> probes : register(t5);  // per probe: s and the optical radius, d and a depth, l and a thickness
Texture3D<float> deckDiffusionTable : register(t6);
SamplerState linearWrap : register(s0);
SamplerState linearClamp : register(s1);
RWStructuredBuffer<float4> results : register(u0);

#include "clouds/particle_lighting.hlsli"

[numthreads(64, 1, 1)]
void main(uint3 id : SV_DispatchThreadID) {
    float4 s = probes[id.x * 3], d = probes[id.x * 3 + 1], l = probes[id.x * 3 + 2];
    float3 scattered = particleScattering(s.xyz, d.xyz, l.xyz, s.w);
    float mean = sampleOpticalDepth(opticalDepthTable, linearWrap, opticalDepthCoordinates(s.xyz, d.xyz), field.tableSizes);
    results[id.x * 2] = float4(scattered, deckMultipleScattering(d.w, l.w, dot(d.xyz, l.xyz)));
    results[id.x * 2 + 1] = float4(mean, solvedSlabMultipleScattering(d.w, l.w, dot(d.xyz, l.xyz)), 0.0, 0.0);
}
