// Epipolar sampling, pass 6: the ray-marching samples (their own interpolation sources) go
// into a list, so that the march runs on them alone (an indirect dispatch).
#include "lightshafts/epipolar_inputs.hlsli"

RWStructuredBuffer<uint> listOut : register(u0);
RWBuffer<uint> listArgumentsOut : register(u1);  // x, y, z groups, then the count

[numthreads(SAMPLE_GROUP, 1, 1)]
void main(uint3 id : SV_DispatchThreadID) {
    if (id.x >= epipolar.sampling.y) return;
    uint2 sources = interpolationSources.Load(int3(id.xy, 0));
    if (sources.x != id.x || sources.y != id.x) return;
    uint slot;
    InterlockedAdd(listArgumentsOut[3], 1, slot);
    listOut[slot] = packEntry(id.xy);
}
