// Probes of the terrain's shader functions, for tests/gpu/TerrainTest.cpp (one thread per query):
//   surface: q.a = (x, z, vertex spacing, mip) -> (surfaceHeight, heightFieldAt, detailHeight, earthDrop)
//   shading: q.a = (albedo rgb, altitude), q.b = (normal xyz, sun visibility), q.c = (up xyz, 0),
//            q.d = (direction to the sun xyz, 0) -> (lambertianRadiance(...) per unit sun irradiance, 0)
// GROUND_LIGHTING (0 to 3) picks the tables as in the terrain's pixel shader. Threads past the
// last query read zeros and write nowhere (out-of-range structured buffer accesses).
#ifndef GROUND_LIGHTING
#define GROUND_LIGHTING 0
#endif
#include "atmosphere/atmosphere_structures.hlsli"
#include "terrain/terrain_structures.hlsli"

cbuffer AtmosphereBuffer : register(b0) { AtmosphereConstants atmosphere; };
#if GROUND_LIGHTING == 3
cbuffer HillaireBuffer : register(b1) { HillaireConstants hillaire; };
#else
cbuffer BrunetonBuffer : register(b1) { BrunetonConstants bruneton; };
#endif
cbuffer TerrainBuffer : register(b2) { TerrainConstants terrain; };

struct Query {
    float4 a, b, c, d;
};
StructuredBuffer<Query> queries : register(t0);
Texture2D<float> heightField : register(t1);
Texture2D<float4> sunTransmittanceTable : register(t2);
Texture2D<float4> skyIrradianceTable : register(t3);
SamplerState linearClamp : register(s0);
RWStructuredBuffer<float4> results : register(u0);

#include "terrain/ground_lighting.hlsli"
#include "terrain/surface.hlsli"

[numthreads(64, 1, 1)]
void surface(uint3 id : SV_DispatchThreadID) {
    float4 q = queries[id.x].a;
    uint mip = (uint)q.w;
    results[id.x] = float4(surfaceHeight(terrain, heightField, q.xy, q.z, mip), heightFieldAt(terrain, heightField, q.xy, mip),
                           detailHeight(q.xy, q.z), earthDrop(q.xy, terrain.field.w));
}

[numthreads(64, 1, 1)]
void shading(uint3 id : SV_DispatchThreadID) {
    Query q = queries[id.x];
    GroundLight light = groundLight(q.a.w, dot(q.c.xyz, q.d.xyz));
    results[id.x] = float4(lambertianRadiance(q.a.rgb, q.b.xyz, q.c.xyz, q.d.xyz, q.b.w, light), 0.0);
}
