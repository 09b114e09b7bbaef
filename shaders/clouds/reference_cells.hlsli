#ifndef FIRMAMENT_REFERENCE_CELLS_HLSLI
#define FIRMAMENT_REFERENCE_CELLS_HLSLI
// The path-traced reference's index tables (clouds/reference_medium.hlsli): per ring, a table of
// (D + 2) x (D + 2) cells, the ring's square of D x D and a margin of one cell, stacked ring by
// ring in rows; per cell, the count of its particles, `layers` slots, and a majorant per slab of
// height.
#include "clouds/cloud_field.hlsli"

// A point's place on the plane (x, z): where the line from the planet's centre through it meets
// the plane y = 0 (cloud_field.hlsli's liftToLayer() undone).
float2 planeOf(float3 position) { return position.xz * (frame.planet.x / (position.y + frame.planet.x)); }

float ringCellSize(uint ring) { return ldexp(field.grid.x, float(ring)); }
// The world index of ring r's first cell (i = 0) along x and z.
int2 ringOrigin(uint ring) {
    int scale = 1 << (field.layout.x - 1 - ring);
    return int2(asint(field.centre.x), asint(field.centre.y)) * scale - int(field.layout.y) / 2;
}
// Ring r's cell under a place of the plane, by its index in the ring's square.
int2 ringLocal(uint ring, float2 plane) { return int2(floor(plane / ringCellSize(ring))) - ringOrigin(ring); }

uint tableWidth() { return field.layout.y + 2; }
// A cell of ring r by its index within the ring's square (-1..D: the margin included).
uint2 tableTexel(uint ring, int2 local) { return uint2(local + 1) + uint2(0, ring * tableWidth()); }
uint firstSlot(uint2 texel) { return (texel.y * tableWidth() + texel.x) * field.layout.z; }
// The shell of the layer's altitudes that holds every particle (half a layer's share of the
// thickness beyond the highest and lowest, with as much again to spare), cut into slabs of height:
// each cell keeps a majorant per slab, of the particles whose altitudes reach into it.
float shellBottom() { return max(field.grid.y - 0.5 * field.grid.z - field.grid.z / float(field.layout.z), 1.0); }
float shellTop() { return field.grid.y + 0.5 * field.grid.z + field.grid.z / float(field.layout.z); }
uint slabCount() { return 2u * field.layout.z; }
float slabHeight() { return (shellTop() - shellBottom()) / float(slabCount()); }
uint slabOf(float altitude) { return uint(clamp(floor((altitude - shellBottom()) / slabHeight()), 0.0, float(slabCount() - 1u))); }
uint majorantIndex(uint2 texel, uint slab) { return (texel.y * tableWidth() + texel.x) * slabCount() + slab; }
// A point's altitude above the planet's surface, without cancelling R against R.
float altitudeOf(float3 position) {
    float R = frame.planet.x;
    return (dot(position.xz, position.xz) + position.y * (2.0 * R + position.y)) / (length(position + float3(0.0, R, 0.0)) + R);
}

bool inTable(int2 local) { return all(local >= -1) && all(local <= int(field.layout.y)); }
bool inSquare(int2 local) { return all(local >= 0) && all(local < int(field.layout.y)); }

#endif
