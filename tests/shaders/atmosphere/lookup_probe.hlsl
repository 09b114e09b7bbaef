// Runs the program's look-up functions at points the test chooses, so that the tables can be
// compared with the CPU reference anywhere, not only at texel centres. Compiled with the
// program's shader folder as the include root.
#include "atmosphere/yusov/lookup.hlsli"

cbuffer AtmosphereBuffer : register(b0) {
    AtmosphereConstants atmosphere;
};

struct Query {
    float4 position;  // xyz: relative to the Earth's centre (m)
    float4 viewDir;   // xyz
    float4 sunDir;    // xyz
};

StructuredBuffer<Query> queries : register(t0);
Texture2D<float4> netDensityLut : register(t1);
Texture3D<float4> scatteringLut : register(t2);
SamplerState linearClamp : register(s0);
RWStructuredBuffer<float4> results : register(u0);

// A look-up at query q, from a table of species (single scattering, all orders) or of radiance
// (the higher orders); w: 1 if the look-up used the half above the horizon.
float4 lookUpAt(Query q, bool species) {
    int side = kHorizonUndecided;
    float3 light = species ? lookUpSpeciesScattering(atmosphere, scatteringLut, linearClamp, q.position.xyz, q.viewDir.xyz, q.sunDir.xyz, side)
                           : lookUpScattering(atmosphere, scatteringLut, linearClamp, q.position.xyz, q.viewDir.xyz, q.sunDir.xyz, side);
    return float4(light, side == kAboveHorizon ? 1.0 : 0.0);
}

[numthreads(64, 1, 1)]
void scattering(uint3 id : SV_DispatchThreadID) { results[id.x] = lookUpAt(queries[id.x], true); }

[numthreads(64, 1, 1)]
void radiance(uint3 id : SV_DispatchThreadID) { results[id.x] = lookUpAt(queries[id.x], false); }

// The sun's transmittance at each query's position, towards its sun direction.
[numthreads(64, 1, 1)]
void transmittance(uint3 id : SV_DispatchThreadID) {
    Query q = queries[id.x];
    float radius = length(q.position.xyz);
    float h = radius - atmosphere.earth.x;
    float3 t = sunTransmittance(atmosphere, netDensityLut, linearClamp, h, dot(q.position.xyz / radius, q.sunDir.xyz));
    results[id.x] = float4(t, 0.0);
}
