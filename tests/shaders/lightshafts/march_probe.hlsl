// For tests/gpu/LightShaftMarchTest.cpp: the light shafts' ray march (lightshafts/ray_march.hlsli)
// along rays the test chooses, through cascades holding a known occluder.
//   march:        q.a = (view direction xyz, ray length) -> (D_lit, D_start, marched begin, marched end)
//   inscattering: the same query -> (shadowed in-scattering rgb per unit irradiance, 0)
//   unshadowed:   the same query -> (the whole ray's in-scattering, as the atmosphere's passes
//                 draw it, rgb per unit irradiance, 0)
//   section:      q.b = (s0, s1, table) -> (eq. 8 over [s0, s1] from that table, rgb, 0)
//   lookUp:       q.b = (s, -, table) -> (the table's light at s along the ray, rgb; T(start -> s), blue)
// The rays start at the camera (inside the atmosphere), probe.camera.
#include "atmosphere/atmosphere_structures.hlsli"
#include "lightshafts/lightshaft_structures.hlsli"
#include "shadows/shadow_structures.hlsli"

cbuffer AtmosphereBuffer : register(b0) { AtmosphereConstants atmosphere; };
cbuffer LightShaftBuffer : register(b1) { LightShaftConstants lightShafts; };
cbuffer ShadowBuffer : register(b2) { ShadowConstants shadows; };
cbuffer ProbeBuffer : register(b3) {
    float4 camera;     // xyz: world position
    float4 toSun;      // xyz: unit vector
};

struct Query {
    float4 a, b;
};
StructuredBuffer<Query> queries : register(t0);
Texture2D<float4> netDensityLut : register(t1);
Texture3D<float4> singleScatteringLut : register(t2);
Texture3D<float4> highOrderScatteringLut : register(t3);
Texture3D<float4> multipleScatteringLut : register(t4);
Texture2D<float> shadowMap : register(t5);
SamplerState linearClamp : register(s0);
SamplerComparisonState shadowComparison : register(s1);
RWStructuredBuffer<float4> results : register(u0);

#include "lightshafts/ray_march.hlsli"

ViewRay probeRay(Query q) {
    ViewRay ray;
    ray.camera = camera.xyz;
    ray.start = camera.xyz + float3(0.0, atmosphere.earth.x, 0.0);
    ray.viewDir = normalize(q.a.xyz);
    ray.offset = 0.0;
    ray.length = q.a.w;
    ray.hitsGround = rayHitsGround(atmosphere, ray.start, ray.viewDir);
    ray.endsAtBoundary = false;
    return ray;
}

[numthreads(64, 1, 1)]
void march(uint3 id : SV_DispatchThreadID) {
    ShadowMarch m = marchShadows(probeRay(queries[id.x]), toSun.xyz, false, 0);
    results[id.x] = float4(m.litLength, m.firstLit, m.begin, m.end);
}

[numthreads(64, 1, 1)]
void inscattering(uint3 id : SV_DispatchThreadID) {
    results[id.x] = float4(shadowedInscattering(probeRay(queries[id.x]), toSun.xyz), 0.0);
}

[numthreads(64, 1, 1)]
void unshadowed(uint3 id : SV_DispatchThreadID) {
    results[id.x] = float4(scatteringAlongRay(probeRay(queries[id.x]), toSun.xyz, lightShafts.mode.x, lightShafts.mode.z, (int)lightShafts.mode.y), 0.0);
}

[numthreads(64, 1, 1)]
void section(uint3 id : SV_DispatchThreadID) {
    Query q = queries[id.x];
    results[id.x] = float4(tableSection((uint)q.b.z, probeRay(q), toSun.xyz, q.b.x, q.b.y), 0.0);
}

[numthreads(64, 1, 1)]
void lookUp(uint3 id : SV_DispatchThreadID) {
    Query q = queries[id.x];
    ViewRay ray = probeRay(q);
    float3 light = lookUpTable((uint)q.b.z, ray.start + ray.viewDir * q.b.x, ray.viewDir, toSun.xyz, ray.hitsGround ? kBelowHorizon : kAboveHorizon);
    results[id.x] = float4(light, transmittanceTo(ray, q.b.x).b);
}
