// Probes of the clouds' shading functions (clouds/particle_lighting.hlsli, optical_depth_table.hlsli)
// for tests/gpu/CloudShadingTest.cpp: per probe an entry point s, a direction d into the unit
// sphere and the sun's direction l; out: the scattering table's single and multiple scattering at
// them, and the optical depth table's mean density along the chord.
#include "clouds/optical_depth_table.hlsli"
#include "clouds/particle_shape.hlsli"

cbuffer CloudShadingBuffer : register(b3) { CloudShadingConstants shading; };
Texture3D<float> opticalDepthTable : register(t2);
Texture3D<float2> scatteringTable : register(t4);
StructuredBuffer<float4> probes : register(t5);  // s, d, l per probe
SamplerState linearWrap : register(s0);
RWStructuredBuffer<float4> results : register(u0);

#include "clouds/particle_lighting.hlsli"

[numthreads(64, 1, 1)]
void main(uint3 id : SV_DispatchThreadID) {
    float3 s = probes[id.x * 3].xyz, d = probes[id.x * 3 + 1].xyz, l = probes[id.x * 3 + 2].xyz;
    float2 scattered = particleScattering(s, d, l);
    float mean = sampleOpticalDepth(opticalDepthTable, linearWrap, opticalDepthCoordinates(s, d), field.tableSizes);
    results[id.x] = float4(scattered, mean, 0.0);
}
