// The valid cells (Yusov 2014, "Particle generation", first step): a thread per cell of the grid
// lists the cells that the density map covers within the particle distance. The list's count is
// an InterlockedAdd on its arguments (Direct3D's append buffers are not translated by Wine's
// vkd3d; docs/building.md).
#include "clouds/cloud_field.hlsli"

StructuredBuffer<uint> cells : register(t0);  // packed ring, i, j (src/clouds/CloudGrid.h)
Texture2D<float> densityMap : register(t1);
RWStructuredBuffer<uint> validCellsOut : register(u0);
RWBuffer<uint> validArgumentsOut : register(u1);  // x, y, z groups, then the count

[numthreads(64, 1, 1)]
void main(uint3 id : SV_DispatchThreadID) {
    uint index = id.x;
    if (index >= field.layout.w) return;
    CloudCell cell = unpackCell(cells[index]);
    float coverage = cellCoverage(densityMap, cell.plane);
    if (!(coverage > 0.0) || !cellInReach(cell)) return;
    uint slot;
    InterlockedAdd(validArgumentsOut[3], 1, slot);
    validCellsOut[slot] = index;
}
