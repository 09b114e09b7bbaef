// Each particle's column along the sun (Yusov 2014, "Computing light occlusion: traversing lists";
// docs/clouds.md, "Light occlusion"): a thread per particle (DispatchIndirect) walks the list of
// the tile under its centre from the sun. For each particle nearer the sun it adds the optical
// depth that the ray from its centre towards the sun crosses in it (the ray against the ellipsoid,
// the chord's mean density from the optical depth table): the column above. Past itself it goes
// on, adding what the ray away from the sun crosses in each particle farther: the column beyond,
// which deck diffusion needs (the light a deck sends back up depends on how much cloud is below).
// Of each column it also keeps the part of the particle's own deck: the cloud that the ray crosses
// without a longer stretch of clear air between it and the particle than a quarter of the
// particle's half-width across the ray (docs/clouds.md, "Deck diffusion": diffuse light leaves a
// deck at a gap). With the early exit, it stops once the two columns together pass the threshold
// (src/clouds/LightSpace.h, kOpacityEarlyExitDepth). The CPU twin is src/reference/
// SunColumnTwin.cpp's sunColumn(), which finds the deck from the union of every chord; this walk
// finds it in one pass, in the list's order (clouds/deck_chords.hlsli).
#include "clouds/deck_chords.hlsli"
#include "clouds/light_space.hlsli"
#include "clouds/optical_depth_table.hlsli"
#include "clouds/particle_shape.hlsli"

Texture3D<float> opticalDepthTable : register(t2);
Buffer<uint> particleArguments : register(t3);  // the particles' count at [3]
Texture2D<uint> tileHeads : register(t4);
StructuredBuffer<uint3> tileNodes : register(t5);
SamplerState linearWrap : register(s0);
RWStructuredBuffer<float4> sunColumn : register(u0);  // by slot: the optical depths above and beyond (xy), and of them the particle's deck (zw)

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
    // The particle's own chord from its centre, along the sun and (as long) away from it, and its
    // half-width across the sun's ray (the ellipsoid's, in the vertical plane through the ray); the
    // deck's chords on either side (clouds/deck_chords.hlsli).
    ParticleHit self;
    float ownReach = hitParticleFrom(p, origin, sun, self) ? self.far : 0.0;
    float sine = dot(sun, self.normal);
    float halfWidth = sqrt(p.centre.w * p.centre.w * sine * sine + p.shape.x * p.shape.x * (1.0 - sine * sine));
    DeckChords deckAbove = emptyDeck(ownReach, halfWidth), deckBeyond = emptyDeck(ownReach, halfWidth);
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
        float start = max(hit.near, 0.0), length = hit.far - start;
        if (length <= 0.0) continue;
        float depth = particleOpticalDepth(q, hit, length, opticalDepthTable, linearWrap);
        if (passed) {
            column.y += depth;
            addChord(deckBeyond, start, hit.far, depth);
        } else {
            column.x += depth;
            addChord(deckAbove, start, hit.far, depth);
        }
        if (threshold > 0.0 && column.x + column.y > threshold) break;
    }
    sunColumn[slot] = float4(column, deckAbove.depth, deckBeyond.depth);
}
