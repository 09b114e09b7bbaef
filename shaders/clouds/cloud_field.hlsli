#ifndef FIRMAMENT_CLOUD_FIELD_HLSLI
#define FIRMAMENT_CLOUD_FIELD_HLSLI
// The cloud field: the cell grid's geometry, the coverage the density map gives a place, and the
// particles a cell holds (Yusov 2014, "Particle generation"; docs/clouds.md). The CPU twin is
// src/clouds/CloudField.cpp and src/reference/CloudFieldTwin.cpp: change them together.
#include "clouds/cloud_structures.hlsli"
#include "common/hash.hlsli"

cbuffer FrameBuffer : register(b0) { FrameConstants frame; };
cbuffer CloudFieldBuffer : register(b1) { CloudFieldConstants field; };

static const float kTwoPi = 6.2831853;

struct CloudCell {
    uint ring;
    int2 world;    // the cell's index in the world along x and z, in its ring's cells
    float size;    // its edge (m)
    float2 plane;  // its middle on the plane (x, z)
};

// A cell of the list (packed i, j: 10 bits each; ring: 4 bits; src/clouds/CloudGrid.h).
CloudCell unpackCell(uint packed) {
    CloudCell cell;
    cell.ring = packed >> 20;
    int i = int(packed & 1023u), j = int((packed >> 10) & 1023u);
    int half = int(field.layout.y) / 2;
    int scale = 1 << (field.layout.x - 1 - cell.ring);
    cell.world = int2(asint(field.centre.x) * scale + i - half, asint(field.centre.y) * scale + j - half);
    cell.size = ldexp(field.grid.x, float(cell.ring));
    cell.plane = (float2(cell.world) + 0.5) * cell.size;
    return cell;
}

// A point of the plane (x, z) lifted to `height` above the planet's surface along the normal
// through it; y is written so that R does not cancel against R in single precision.
float3 liftToLayer(float2 xz, float height) {
    float radius = frame.planet.x;
    float d2 = xz.x * xz.x + xz.y * xz.y;
    float len = sqrt(d2 + radius * radius);
    float scale = (radius + height) / len;
    float y = height * (radius / len) - radius * d2 / (len * (len + radius));
    return float3(xz.x * scale, y, xz.y * scale);
}

// One tap of the density map: bilinear between four texels, the map repeating every
// 1 / inversePeriod metres, moved by the wind's offset. Loads, not a sampler, so that the CPU
// twin computes the same weights.
float densityTap(Texture2D<float> map, float2 xz, float inversePeriod, float2 offset) {
    float res = field.coverage.w;
    float2 c = (xz - offset) * inversePeriod * res - 0.5;
    float2 f = floor(c);
    float2 t = c - f;
    int2 i0 = int2(f);
    uint mask = uint(res) - 1u;
    uint2 a = uint2(i0) & mask;
    uint2 b = uint2(i0 + 1) & mask;
    float v00 = map.Load(int3(a.x, a.y, 0));
    float v10 = map.Load(int3(b.x, a.y, 0));
    float v01 = map.Load(int3(a.x, b.y, 0));
    float v11 = map.Load(int3(b.x, b.y, 0));
    float bottom = v00 + t.x * (v10 - v00);
    float top = v01 + t.x * (v11 - v01);
    return bottom + t.y * (top - bottom);
}

// The cell's coverage, 0..1: the geometric mean of the map's two taps above the threshold that
// Cloudiness sets. It is also the cloud's height in the cell: layers fill from the bottom.
float cellCoverage(Texture2D<float> map, float2 xz) {
    float n = sqrt(densityTap(map, xz, field.coverage.y, field.wind.xy) * densityTap(map, xz, field.coverage.z, field.wind.zw));
    float cloudiness = field.coverage.x;
    return saturate((n - (1.0 - cloudiness)) / max(cloudiness, 0.01));
}

// Whether a cell can hold a particle within the particle distance of the camera.
bool cellInReach(CloudCell cell) {
    float3 middle = liftToLayer(cell.plane, field.grid.y);
    return length(middle - frame.cameraPosition.xyz) - (1.5 * cell.size + 0.5 * field.grid.z) <= field.grid.w;
}

// The particle of `layer` in a cell of `coverage`; false when the layer is empty or the particle
// lies beyond the particle distance. Its place, size and pulses come from a hash of the cell's
// world index: a cell's particles stay where they are while the grid moves.
bool cellParticle(CloudCell cell, float coverage, uint layer, out CloudParticle p) {
    p = (CloudParticle)0;
    float layers = float(field.layout.z);
    float layerDensity = saturate(coverage * layers - float(layer));
    if (!(layerDensity > 0.0)) return false;
    uint seed = hash32(asuint(cell.world.x) ^ hash32(asuint(cell.world.y) ^ hash32(cell.ring * 32u + layer + 0x9e3779b9u)));
    float r[7];
    [unroll] for (uint k = 0; k < 7; ++k) r[k] = unitFromHash(hash32(seed + k));
    float thickness = field.grid.z;
    float2 at = cell.plane + float2(r[0] - 0.5, r[1] - 0.5) * (0.6 * cell.size);
    float height = field.grid.y + ((float(layer) + 0.5) / layers - 0.5) * thickness + (r[2] - 0.5) * 0.5 * thickness / layers;
    float3 centre = liftToLayer(at, height);
    float pulse = 0.9 + 0.1 * sin(field.animation.x + kTwoPi * r[4]);
    float horizontal = cell.size * (0.7 + 0.4 * r[3]) * saturate(layerDensity * 3.0) * pulse;
    p.centre = float4(centre, horizontal);
    p.shape = float4(min(horizontal, 0.75 * thickness / layers), layerDensity * (0.8 + 0.2 * sin(field.animation.y + kTwoPi * r[5])),
                     kTwoPi * r[6], float(cell.ring));
    return length(centre - frame.cameraPosition.xyz) - horizontal <= field.grid.w;
}

#endif
