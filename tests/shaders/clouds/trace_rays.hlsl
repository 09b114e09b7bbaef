// The clouds' path-traced reference (clouds/reference_paths.hlsli) under the CPU twin's lighting
// (src/reference/CloudPathTracer.h, CloudLighting): a sun of constant irradiance reference.light.rgb
// along frame.directionToSun, a sky of constant radiance reference.light.w, no air, and, with
// reference.options.y, a Lambertian plane at y = reference.ground.x of albedo ground.yzw.
// A thread per ray of `rays` (origin, direction), reference.paths.y paths each: the mean light
// and, in w, the mean light's standard error.
#include "clouds/cloud_structures.hlsli"

cbuffer CloudReferenceBuffer : register(b3) { CloudReferenceConstants reference; };

#include "clouds/reference_medium.hlsli"

float3 sunAt(float3 x) { return reference.light.rgb; }
void segment(float3 x, float3 d, float distance, out float3 transmittance, out float3 light) {
    transmittance = 1.0;
    light = distance >= 3.0e38 ? reference.light.w : 0.0;  // the sky beyond
}
float groundDistance(float3 x, float3 d) {
    if (reference.options.y == 0 || d.y >= 0.0 || x.y <= reference.ground.x) return 3.0e38;
    return (reference.ground.x - x.y) / d.y;
}
float3 groundAlbedo(float3 x) { return reference.ground.yzw; }
float3 groundNormal(float3 x) { return float3(0.0, 1.0, 0.0); }

#include "clouds/reference_paths.hlsli"

struct TestRay {
    float4 origin;
    float4 direction;
};
StructuredBuffer<TestRay> rays : register(t0);
RWStructuredBuffer<float4> results : register(u0);

[numthreads(64, 1, 1)]
void main(uint3 id : SV_DispatchThreadID) {
    if (id.x >= reference.paths.w) return;
    TestRay ray = rays[id.x];
    uint state = hash32(id.x ^ hash32(reference.paths.z));
    float3 sum = 0.0;
    float squares = 0.0;
    for (uint k = 0; k < reference.paths.y; ++k) {
        PathSample s = tracePath(ray.origin.xyz, ray.direction.xyz, 3.0e38, false, reference.options.z, state);
        sum += s.light;
        float grey = dot(s.light, 1.0 / 3.0);
        squares += grey * grey;
    }
    float n = float(max(reference.paths.y, 1u));
    float3 mean = sum / n;
    float meanGrey = dot(mean, 1.0 / 3.0);
    results[id.x] = float4(mean, sqrt(max(squares / n - meanGrey * meanGrey, 0.0) / n));
}

// The medium itself at points of `rays` (origin): x the extinction (clouds/reference_medium.hlsli),
// y the majorant of the walk's first stretch from the point along `direction`, which covers it.
[numthreads(64, 1, 1)]
void extinction_at(uint3 id : SV_DispatchThreadID) {
    if (id.x >= reference.paths.w) return;
    TestRay ray = rays[id.x];
    MajorantWalk walk = beginWalk(ray.origin.xyz, ray.direction.xyz, 3.0e38);
    float t0, t1, majorant;
    bool inside = nextStretch(walk, t0, t1, majorant) && t0 <= 0.0;
    results[id.x] = float4(referenceExtinction(ray.origin.xyz), inside ? majorant : 0.0, t0, t1);
}
