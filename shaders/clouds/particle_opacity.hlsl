// Each particle's column along the sun (Yusov 2014, "Computing light occlusion: traversing lists";
// docs/clouds.md, "Light occlusion"): a thread per particle (DispatchIndirect) walks the list of
// the tile under its centre from the sun. For each particle nearer the sun it adds the optical
// depth that the ray from its centre towards the sun crosses in it (the ray against the ellipsoid,
// the chord's mean density from the optical depth table): the column above. Past itself it goes
// on, adding what the ray away from the sun crosses in each particle farther: the column beyond,
// which deck diffusion needs (the light a deck sends back up depends on how much cloud is below).
// With the early exit, it stops once the two together pass the threshold (src/clouds/
// LightSpace.h, kOpacityEarlyExitDepth). The CPU twin is src/reference/SunColumnTwin.cpp's sunColumn().
#include "clouds/light_space.hlsli"
#include "clouds/optical_depth_table.hlsli"
#include "clouds/particle_shape.hlsli"

Texture3D<float> opticalDepthTable : register(t2);
Buffer<uint> particleArguments : register(t3);  // the particles' count at [3]
Texture2D<uint> tileHeads : register(t4);
StructuredBuffer<uint3> tileNodes : register(t5);
SamplerState linearWrap : register(s0);
RWStructuredBuffer<float2> sunColumn : register(u0);  // by slot: the optical depths above and beyond

[numthreads(256, 1, 1)]
void main(uint3 id : SV_DispatchThreadID) {
    if (id.x >= min(particleArguments[3], field.centre.z)) return;
    uint slot = sortedKeys[id.x].y;
    CloudParticle p = particles[slot];
    float3 origin = p.centre.xyz, sun = lightSpace.sun.xyz;
    float own = towardSun(origin);
    int2 tile = lightSpaceTile(origin);
    uint n = lightSpaceResolution();
    float2 column = 0.0;
    float threshold = lightSpace.up.w;
    bool passed = false;  // itself reached: the rest are farther from the sun
    uint node = (tile.x >= 0 && tile.y >= 0 && uint(tile.x) < n && uint(tile.y) < n) ? tileHeads.Load(int3(tile, 0)) : kNoParticle;
    // The bound guards a broken link; a list never holds more than the particles.
    for (uint guard = 0; guard < 1048576u && node != kNoParticle; ++guard) {
        uint3 entry = tileNodes[node];
        node = entry.y;
        if (entry.x == slot) {
            passed = true;
            continue;
        }
        if (asfloat(entry.z) == own) continue;  // as far as itself: neither nearer nor farther
        passed = passed || asfloat(entry.z) < own;
        CloudParticle q = particles[entry.x];
        ParticleHit hit;
        if (!hitParticleFrom(q, origin, passed ? -sun : sun, hit)) continue;
        float length = hit.far - max(hit.near, 0.0);
        if (length <= 0.0) continue;
        float depth = particleOpticalDepth(q, hit, length, opticalDepthTable, linearWrap);
        column += passed ? float2(0.0, depth) : float2(depth, 0.0);
        if (threshold > 0.0 && column.x + column.y > threshold) break;
    }
    sunColumn[slot] = column;
}
