// The clouds' path-traced reference: its index of the particles (docs/clouds.md, "Path-traced
// reference"; clouds/reference_medium.hlsli describes it).
//  - list_particles: DispatchIndirect, a thread per particle: the particle's cell recovered from
//    its centre (the ring it was generated in, and the plane's place under it; generation puts it
//    within 0.3 of a cell of its cell's middle), its slot appended to the cell's.
//  - cell_majorants: a thread per cell of every ring's table: for each slab of height, the sum of
//    the densities of the particles that can reach it, times the extinction at density 1. A
//    particle's altitudes are its centre's within its bounding radius.
#include "clouds/particle_shape.hlsli"
#include "clouds/reference_cells.hlsli"

cbuffer CloudReferenceBuffer : register(b3) { CloudReferenceConstants reference; };

Buffer<uint> particleArguments : register(t3);  // the particles' count at [3]

#ifdef LIST_PARTICLES
RWTexture2D<uint> cellCounts : register(u0);
RWStructuredBuffer<uint> cellSlots : register(u1);

[numthreads(256, 1, 1)]
void list_particles(uint3 id : SV_DispatchThreadID) {
    if (id.x >= min(particleArguments[3], field.centre.z)) return;
    CloudParticle p = particles[id.x];
    uint ring = uint(p.shape.w);
    if (ring >= field.layout.x) return;
    int2 local = ringLocal(ring, planeOf(p.centre.xyz));
    if (!inSquare(local)) return;
    uint2 texel = tableTexel(ring, local);
    uint k;
    InterlockedAdd(cellCounts[texel], 1u, k);
    if (k < field.layout.z) cellSlots[firstSlot(texel) + k] = id.x;
}
#else
Texture2D<uint> cellCounts : register(t10);
StructuredBuffer<uint> cellSlots : register(t11);
RWStructuredBuffer<float> cellMajorants : register(u0);  // per cell and slab (majorantIndex)

// The densities of ring r's particles in the cells of world index lower..upper (inclusive) whose
// altitudes reach [bottom, top].
float densityIn(int ring, int2 lower, int2 upper, float bottom, float top) {
    if (ring < 0 || ring >= int(field.layout.x)) return 0.0;
    int2 origin = ringOrigin(uint(ring));
    float sum = 0.0;
    for (int j = lower.y; j <= upper.y; ++j)
        for (int i = lower.x; i <= upper.x; ++i) {
            int2 local = int2(i, j) - origin;
            if (!inSquare(local)) continue;
            uint2 texel = tableTexel(uint(ring), local);
            uint count = min(cellCounts.Load(int3(texel, 0)), field.layout.z);
            for (uint k = 0; k < count; ++k) {
                CloudParticle p = particles[cellSlots[firstSlot(texel) + k]];
                float altitude = altitudeOf(p.centre.xyz), reach = max(p.centre.w, p.shape.x);
                if (altitude + reach >= bottom && altitude - reach <= top) sum += max(p.shape.y, 0.0);
            }
        }
    return sum;
}

[numthreads(8, 8, 1)]
void cell_majorants(uint3 id : SV_DispatchThreadID) {
    uint width = tableWidth();
    if (id.x >= width || id.y >= width * field.layout.x) return;
    int ring = int(id.y / width);
    int2 world = int2(id.x, id.y % width) - 1 + ringOrigin(uint(ring));
    uint first = majorantIndex(id.xy, 0u);
    // Ring r's own 3 x 3; the finer ring's cells under this one and one around (4 x 4); the
    // coarser ring's cell over it and one around (3 x 3). Arithmetic shifts floor negatives.
    // Each slab of height, a metre wider each way (the walk looks a centimetre ahead).
    float height = slabHeight();
    [loop] for (uint slab = 0; slab < slabCount(); ++slab) {
        float bottom = shellBottom() + height * float(slab) - 1.0, top = bottom + height + 2.0;
        float sum = densityIn(ring, world - 1, world + 1, bottom, top) + densityIn(ring - 1, world * 2 - 1, world * 2 + 2, bottom, top) +
                    densityIn(ring + 1, (world >> 1) - 1, (world >> 1) + 1, bottom, top);
        cellMajorants[first + slab] = sum * kCloudExtinction;
    }
}
#endif
