// Runs Bruneton and Neyret's look-up functions at points the test chooses, so that their tables
// can be compared with the CPU reference and with Yusov's tables anywhere. Compiled with the
// program's shader folder as the include root.
#include "atmosphere/bruneton/lookup.hlsli"

cbuffer AtmosphereBuffer : register(b0) {
    AtmosphereConstants atmosphere;
};
cbuffer BrunetonBuffer : register(b1) {
    BrunetonConstants bruneton;
};

struct Query {
    float4 position;  // xyz: relative to the Earth's centre (m)
    float4 viewDir;   // xyz
    float4 sunDir;    // xyz
};

StructuredBuffer<Query> queries : register(t0);
Texture2D<float4> transmittanceTable : register(t1);
Texture2D<float4> irradianceTable : register(t2);
Texture3D<float4> inscatterTable : register(t3);
SamplerState linearClamp : register(s0);
RWStructuredBuffer<float4> results : register(u0);

// The in-scattered radiance per unit sun irradiance along the whole ray (to the ground or the
// top of the atmosphere), as render.hlsl reads it; w: 1 if the ray meets the ground.
[numthreads(64, 1, 1)]
void inscatter(uint3 id : SV_DispatchThreadID) {
    Query q = queries[id.x];
    float r = length(q.position.xyz);
    float mu = dot(q.position.xyz, q.viewDir.xyz) / r;
    float muS = dot(q.position.xyz, q.sunDir.xyz) / r;
    float nu = dot(q.viewDir.xyz, q.sunDir.xyz);
    bool toGround = mu < cosHorizonAtRadius(atmosphere, r);
    float4 s = lookUpInscatter(atmosphere, bruneton, inscatterTable, linearClamp, r - atmosphere.earth.x, mu, muS, nu, toGround);
    float3 radiance = max(s.rgb * rayleighPhase(nu) + mieFromRed(atmosphere, s) * miePhase(nu, atmosphere.mieScattering.w), 0.0);
    results[id.x] = float4(radiance, toGround ? 1.0 : 0.0);
}

// The sun's transmittance at each query's position towards its sun direction.
[numthreads(64, 1, 1)]
void transmittance(uint3 id : SV_DispatchThreadID) {
    Query q = queries[id.x];
    float r = length(q.position.xyz);
    results[id.x] = float4(sunTransmittanceAt(atmosphere, bruneton, transmittanceTable, linearClamp, r, dot(q.position.xyz, q.sunDir.xyz) / r), 0.0);
}

// The sky's irradiance on a horizontal surface at each query's position.
[numthreads(64, 1, 1)]
void irradiance(uint3 id : SV_DispatchThreadID) {
    Query q = queries[id.x];
    float r = length(q.position.xyz);
    results[id.x] = float4(irradianceAt(atmosphere, bruneton, irradianceTable, linearClamp, r, dot(q.position.xyz, q.sunDir.xyz) / r), 0.0);
}
