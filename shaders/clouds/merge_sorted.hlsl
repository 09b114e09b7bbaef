// One merge pass of the sort: sorted runs of `run` keys are merged in pairs. Each key finds its
// place by its rank in its own run plus, by binary search, the number of keys of the other run
// drawn before it. Driven by DispatchIndirect over the particles; the runs double each pass.
#include "clouds/cloud_sort.hlsli"

cbuffer CloudSortBuffer : register(b2) { CloudSortConstants sortPass; };

StructuredBuffer<uint2> keysIn : register(t1);
RWStructuredBuffer<uint2> keysOut : register(u0);

[numthreads(256, 1, 1)]
void main(uint3 id : SV_DispatchThreadID) {
    uint count = particleCount();
    uint index = id.x;
    if (index >= count) return;
    uint run = sortPass.merge.x;
    uint pairStart = index & ~(2u * run - 1u);
    bool firstRun = (index & run) == 0;
    uint ownStart = firstRun ? pairStart : pairStart + run;
    uint otherStart = firstRun ? pairStart + run : pairStart;
    uint otherEnd = max(min(otherStart + run, count), otherStart);
    uint2 key = keysIn[index];
    // Ties between the runs (none: slots differ) would keep the first run's key first.
    uint low = otherStart, high = otherEnd;
    while (low < high) {
        uint middle = (low + high) / 2;
        uint2 other = keysIn[middle];
        bool before = firstRun ? drawnBefore(other, key) : !drawnBefore(key, other);
        if (before) low = middle + 1;
        else high = middle;
    }
    keysOut[pairStart + (index - ownStart) + (low - otherStart)] = key;
}
