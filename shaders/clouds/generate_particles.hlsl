// Particle generation (Yusov 2014, "Particle generation", second step): driven by
// DispatchIndirect over the valid cells, a thread per cell writes a particle per layer its
// coverage fills, and the particle's sort key: its distance from the camera and its slot.
#include "clouds/cloud_field.hlsli"

StructuredBuffer<uint> cells : register(t0);
Texture2D<float> densityMap : register(t1);
StructuredBuffer<uint> validCells : register(t2);
Buffer<uint> validArguments : register(t3);  // the valid cells' count at [3]
RWStructuredBuffer<CloudParticle> particlesOut : register(u0);
RWStructuredBuffer<uint2> keysOut : register(u1);       // x: distance (float bits); y: slot
RWBuffer<uint> particleArgumentsOut : register(u2);  // the particles' count at [3], beyond the capacity too

[numthreads(64, 1, 1)]
void main(uint3 id : SV_DispatchThreadID) {
    if (id.x >= validArguments[3]) return;
    CloudCell cell = unpackCell(cells[validCells[id.x]]);
    float coverage = cellCoverage(densityMap, cell.plane);
    for (uint layer = 0; layer < field.layout.z; ++layer) {
        CloudParticle p;
        if (!cellParticle(cell, coverage, layer, p)) continue;
        uint slot;
        InterlockedAdd(particleArgumentsOut[3], 1, slot);
        if (slot >= field.centre.z) continue;  // over the capacity: counted, not kept
        particlesOut[slot] = p;
        keysOut[slot] = uint2(asuint(length(p.centre.xyz - frame.cameraPosition.xyz)), slot);
    }
}
