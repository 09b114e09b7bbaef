// The sort's first pass: each group sorts a block of 256 keys in group-shared memory with a
// bitonic network (Batcher 1968); merge_sorted.hlsl then merges the blocks. Driven by
// DispatchIndirect over the particles.
#include "clouds/cloud_sort.hlsli"

RWStructuredBuffer<uint2> keys : register(u0);

static const uint kBlock = 256;
groupshared uint2 block[kBlock];

[numthreads(256, 1, 1)]
void main(uint3 group : SV_GroupID, uint thread : SV_GroupIndex) {
    uint count = particleCount();
    uint index = group.x * kBlock + thread;
    // Past the count, keys that every particle is drawn before.
    block[thread] = index < count ? keys[index] : uint2(0u, 0xffffffffu);
    GroupMemoryBarrierWithGroupSync();
    for (uint size = 2; size <= kBlock; size <<= 1) {
        for (uint stride = size >> 1; stride > 0; stride >>= 1) {
            uint partner = thread ^ stride;
            if (partner > thread) {
                uint2 a = block[thread], b = block[partner];
                // Runs whose bit `size` is clear are put in drawing order, the others reversed.
                bool forward = (thread & size) == 0;
                bool swap = forward ? drawnBefore(b, a) : drawnBefore(a, b);
                if (swap) {
                    block[thread] = b;
                    block[partner] = a;
                }
            }
            GroupMemoryBarrierWithGroupSync();
        }
    }
    if (index < count) keys[index] = block[thread];
}
