// Probe of the clouds' shadow map reader (shadows/cloud_shadow.hlsli) for
// tests/gpu/CloudParticlesTest.cpp: per query a world point (xyz); out: the share of the sun's
// light the clouds let reach it, cloudTransmittance(point).
#include "shadows/shadow_structures.hlsli"

cbuffer CloudShadowBuffer : register(b0) { CloudShadowConstants cloudShadow; };
Texture2DArray<float4> cloudShadowMap : register(t0);
StructuredBuffer<float4> queries : register(t1);
RWStructuredBuffer<float> results : register(u0);

#include "shadows/cloud_shadow.hlsli"

[numthreads(64, 1, 1)]
void main(uint3 id : SV_DispatchThreadID) {
    results[id.x] = cloudTransmittance(queries[id.x].xyz);
}
