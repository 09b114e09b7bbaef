// Each particle's sun transmittance (Yusov 2014, "Computing light occlusion: traversing lists";
// docs/clouds.md, "Light occlusion"): a thread per particle (DispatchIndirect) walks the list of
// the tile under its centre from the sun, adding the optical depth that the ray from its centre
// to the sun crosses in each particle nearer the sun (the ray against the ellipsoid, the chord's
// mean density from the optical depth table), until it reaches itself, or, with the early exit,
// until the transmittance falls below the threshold (the sun's transmittance at which the
// multiply scattered light's is 0.01: src/clouds/LightSpace.h). The CPU twin is
// src/clouds/LightSpace.cpp.
#include "clouds/light_space.hlsli"
#include "clouds/optical_depth_table.hlsli"
#include "clouds/particle_shape.hlsli"

Texture3D<float> opticalDepthTable : register(t2);
Buffer<uint> particleArguments : register(t3);  // the particles' count at [3]
Texture2D<uint> tileHeads : register(t4);
StructuredBuffer<uint3> tileNodes : register(t5);
SamplerState linearWrap : register(s0);
RWStructuredBuffer<float> sunTransmittance : register(u0);  // by slot

[numthreads(256, 1, 1)]
void main(uint3 id : SV_DispatchThreadID) {
    if (id.x >= min(particleArguments[3], field.centre.z)) return;
    uint slot = sortedKeys[id.x].y;
    CloudParticle p = particles[slot];
    float3 origin = p.centre.xyz, sun = lightSpace.sun.xyz;
    float own = towardSun(origin);
    int2 tile = lightSpaceTile(origin);
    uint n = lightSpaceResolution();
    float opticalDepth = 0.0;
    float threshold = lightSpace.up.w;
    uint node = (tile.x >= 0 && tile.y >= 0 && uint(tile.x) < n && uint(tile.y) < n) ? tileHeads.Load(int3(tile, 0)) : kNoParticle;
    // The bound guards a broken link; a list never holds more than the particles.
    for (uint guard = 0; guard < 1048576u && node != kNoParticle; ++guard) {
        uint3 entry = tileNodes[node];
        node = entry.y;
        if (entry.x == slot || asfloat(entry.z) < own) break;  // itself: the rest are farther from the sun
        if (asfloat(entry.z) == own) continue;  // as far as itself: not in front
        CloudParticle q = particles[entry.x];
        ParticleHit hit;
        if (!hitParticleFrom(q, origin, sun, hit)) continue;
        float length = hit.far - max(hit.near, 0.0);
        if (length <= 0.0) continue;
        opticalDepth += particleOpticalDepth(q, hit, length, opticalDepthTable, linearWrap);
        if (exp(-opticalDepth) < threshold) break;
    }
    sunTransmittance[slot] = exp(-opticalDepth);
}
