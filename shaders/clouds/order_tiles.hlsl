// Orders each tile's list from the sun (docs/clouds.md, "Light occlusion"): an insertion sort of
// the linked list in place, nearest the sun first, by the distance toward the sun each node
// carries. A thread per tile; no list is too long for it.
#include "clouds/light_space.hlsli"

RWTexture2D<uint> tileHeads : register(u0);
RWStructuredBuffer<uint3> tileNodes : register(u1);

[numthreads(8, 8, 1)]
void main(uint3 id : SV_DispatchThreadID) {
    uint n = lightSpaceResolution();
    if (id.x >= n || id.y >= n) return;
    uint node = tileHeads[id.xy];
    uint sorted = kNoParticle;
    // The bounds guard a broken link: a list never holds more nodes than the pool.
    for (uint guard = 0; guard < 1048576u && node != kNoParticle; ++guard) {
        uint3 entry = tileNodes[node];
        uint next = entry.y;
        float toward = asfloat(entry.z);
        if (sorted == kNoParticle || toward >= asfloat(tileNodes[sorted].z)) {
            tileNodes[node].y = sorted;
            sorted = node;
        } else {
            uint previous = sorted;
            uint after = tileNodes[previous].y;
            for (uint step = 0; step < 1048576u && after != kNoParticle && asfloat(tileNodes[after].z) > toward; ++step) {
                previous = after;
                after = tileNodes[previous].y;
            }
            tileNodes[node].y = after;
            tileNodes[previous].y = node;
        }
        node = next;
    }
    tileHeads[id.xy] = sorted;
}
