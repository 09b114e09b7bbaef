#ifndef FIRMAMENT_REFERENCE_MEDIUM_HLSLI
#define FIRMAMENT_REFERENCE_MEDIUM_HLSLI
// The medium the particles describe, as the clouds' path-traced reference walks it
// (docs/clouds.md, "Path-traced reference"). The CPU twin is ParticleMedium
// (src/reference/CloudMedium.cpp): the same density functions, summed where particles overlap.
//
// The index is the cloud grid itself. Generation puts a cell's particles within 0.3 of a cell of
// its middle, at most 1.1 cells wide, so a particle reaches only the 3 x 3 cells of its ring
// around its own. Each ring has a table of (D + 2) x (D + 2) cells (its square and a margin of
// one cell): the slots of the particles generated in each (clouds/reference_index.hlsl), and a
// majorant, the sum of the densities of every particle that can reach the cell (its ring's 3 x 3
// neighbours, the finer ring's 4 x 4 and the coarser ring's 3 x 3) times the extinction at
// density 1. A point's territory is the finest ring whose square holds it; a ray walks the
// territories' cells, whose sides are planes through the planet's centre (a cell is a column
// along the vertical), within the shell of the layer's altitudes.
//
// The includer declares cbuffer `reference` (CloudReferenceConstants).
#include "clouds/particle_density.hlsli"
#include "clouds/particle_shape.hlsli"
#include "clouds/reference_cells.hlsli"

Texture2D<uint> cellCounts : register(t10);      // particles listed per cell; (D + 2) wide, (D + 2) rows per ring
StructuredBuffer<uint> cellSlots : register(t11);  // per cell, `layers` slots
StructuredBuffer<float> cellMajorants : register(t12);  // per cell and slab of height (1/m; majorantIndex)

static const float kNoCollision = -1.0;

// One particle's extinction at `position` (1/m): its density function in its unit-sphere space,
// turned by its azimuth as the optical depth table is (CloudMedium.cpp, particleExtinction).
float particleExtinctionAt(CloudParticle p, float3 position) {
    float3 tangent, normal, bitangent;
    particleFrame(p.centre.xyz, tangent, normal, bitangent);
    float3 offset = position - p.centre.xyz;
    float3 unit = float3(dot(offset, tangent) / p.centre.w, dot(offset, normal) / p.shape.x, dot(offset, bitangent) / p.centre.w);
    if (dot(unit, unit) >= 1.0 || !(p.shape.y > 0.0)) return 0.0;
    float c = cos(p.shape.z), s = sin(p.shape.z);
    float3 turned = float3(unit.x * c - unit.z * s, unit.y, unit.x * s + unit.z * c);
    return p.shape.y * kCloudExtinction * particleDensity(turned, reference.options.x);
}

// The extinction at `position` (1/m): every particle of every ring whose 3 x 3 cells around the
// point's cell hold it.
float referenceExtinction(float3 position) {
    float2 plane = planeOf(position);
    int D = int(field.layout.y), quarter = D / 4;
    uint layers = field.layout.z;
    float sum = 0.0;
    // One loop over (ring, neighbour, particle), so that the density function is compiled once.
    uint ring = 0, neighbour = 0, k = 0, count = 0, first = 0;
    bool ringNear = false;
    int2 local = int2(0, 0);
    [loop] for (uint guard = 0; guard < 4096u; ++guard) {
        if (k < count) {
            sum += particleExtinctionAt(particles[cellSlots[first + k]], position);
            ++k;
            continue;
        }
        // The next neighbour cell (or ring).
        if (!ringNear || neighbour == 9) {
            if (ringNear || guard > 0) ++ring;
            if (ring >= field.layout.x) break;
            local = ringLocal(ring, plane);
            // Its 3 x 3 cells: not when all are outside the square, or deep in the finer ring's hole.
            ringNear = inTable(local) && !(ring > 0 && all(local >= quarter + 1 && local < D - quarter - 1));
            neighbour = 0;
            count = 0;
            k = 0;
            continue;
        }
        int2 cell = local + int2(int(neighbour % 3) - 1, int(neighbour / 3) - 1);
        ++neighbour;
        k = 0;
        count = 0;
        if (!inSquare(cell)) continue;
        uint2 texel = tableTexel(ring, cell);
        count = min(cellCounts.Load(int3(texel, 0)), layers);
        first = firstSlot(texel);
    }
    return sum;
}

// The ray's stretches inside the layer's shell of altitudes, and within the field's column (the
// outer ring's square and its margin): at most two, [t0.x, t1.x] and [t0.y, t1.y].
float2 sphereRoots(float3 origin, float3 direction, float radius) {
    // |o - C|^2 - r^2 without cancelling R against R: C = (0, -R, 0), r = R + h.
    float R = frame.planet.x, h = radius - R;
    float c = dot(origin.xz, origin.xz) + origin.y * (2.0 * R + origin.y) - h * (2.0 * R + h);
    float b = dot(origin, direction) + R * direction.y;
    float discriminant = b * b - c;
    if (discriminant < 0.0) return float2(1.0, -1.0);  // missed
    float q = -(b + (b >= 0.0 ? 1.0 : -1.0) * sqrt(discriminant));
    float a = q, other = abs(q) > 0.0 ? c / q : 0.0;
    return float2(min(a, other), max(a, other));
}

// The column over the plane's x in [x0, x1] (a pair of planes through the planet's centre):
// the ray's stretch [enter, leave] where R x / (y + R) lies between them.
void clipToColumn(float3 origin, float3 direction, float x0, float x1, float ox, float dx, inout float enter, inout float leave) {
    float R = frame.planet.x, w = origin.y + R;
    // f(t) = R (ox + t dx) - X (w + t dy): >= 0 on the side beyond X.
    float a0 = R * ox - x0 * w, b0 = R * dx - x0 * direction.y;
    float a1 = x1 * w - R * ox, b1 = x1 * direction.y - R * dx;
    if (abs(b0) < 1e-20) { if (a0 < 0.0) leave = -1.0; }
    else if (b0 > 0.0) enter = max(enter, -a0 / b0);
    else leave = min(leave, -a0 / b0);
    if (abs(b1) < 1e-20) { if (a1 < 0.0) leave = -1.0; }
    else if (b1 > 0.0) enter = max(enter, -a1 / b1);
    else leave = min(leave, -a1 / b1);
}

struct MajorantWalk {
    float3 origin, direction;
    float2 start, end;  // the stretches in the shell and the field
    uint stretch;       // the one walked
    float t;            // how far the walk has come
    uint steps;         // a guard against a walk that does not advance
};

MajorantWalk beginWalk(float3 origin, float3 direction, float tMax) {
    MajorantWalk w;
    w.origin = origin;
    w.direction = direction;
    w.stretch = 0;
    w.t = 0.0;
    w.steps = 0;
    float R = frame.planet.x;
    float2 outer = sphereRoots(origin, direction, R + shellTop());
    float2 inner = sphereRoots(origin, direction, R + shellBottom());
    // The field's column: the outer ring's square and its margin.
    uint last = field.layout.x - 1;
    float size = ringCellSize(last);
    float2 lower = float2(ringOrigin(last) - 1) * size, upper = float2(ringOrigin(last) + int(field.layout.y) + 1) * size;
    float enter = 0.0, leave = tMax;
    clipToColumn(origin, direction, lower.x, upper.x, origin.x, direction.x, enter, leave);
    clipToColumn(origin, direction, lower.y, upper.y, origin.z, direction.z, enter, leave);
    enter = max(enter, outer.x);
    leave = min(leave, outer.y);
    // Inside the outer sphere and outside the inner one.
    w.start = float2(enter, max(enter, inner.y));
    w.end = float2(inner.y >= inner.x ? min(leave, inner.x) : leave, inner.y >= inner.x ? leave : -1.0);
    return w;
}

// The next stretch [t0, t1] of the walk with a bound of the extinction on it; false at the end.
// A stretch lies in one cell of its territory and one slab of height, whose majorant holds a
// twentieth of a cell and a metre beyond them.
bool nextStretch(inout MajorantWalk w, out float t0, out float t1, out float majorant) {
    t0 = 0.0;
    t1 = 0.0;
    majorant = 0.0;
    [loop] for (; w.stretch < 2 && w.steps < 65536; ++w.steps) {
        float start = w.stretch == 0 ? w.start.x : w.start.y, end = w.stretch == 0 ? w.end.x : w.end.y;
        w.t = max(w.t, start);
        if (w.t >= end) {
            ++w.stretch;
            continue;
        }
        // The territory of a point a little ahead, so that a boundary the walk stands on is behind.
        float3 at = w.origin + w.direction * w.t;
        float2 plane = planeOf(at + w.direction * 0.01);
        uint ring = 0;
        int2 local = int2(0, 0);
        bool found = false;
        [loop] for (; ring < field.layout.x; ++ring) {
            local = ringLocal(ring, plane);
            if (inSquare(local) || (ring == field.layout.x - 1 && inTable(local))) {
                found = true;
                break;
            }
        }
        if (!found) {  // at the field's edge: the column was clipped to it
            ++w.stretch;
            continue;
        }
        float size = ringCellSize(ring);
        int2 world = local + ringOrigin(ring);
        float leave = end, enter = -3.0e38;
        clipToColumn(w.origin, w.direction, float(world.x) * size, float(world.x + 1) * size, w.origin.x, w.direction.x, enter, leave);
        clipToColumn(w.origin, w.direction, float(world.y) * size, float(world.y + 1) * size, w.origin.z, w.direction.z, enter, leave);
        // The slab of height: the stretch ends where the ray crosses either of its spheres.
        uint slab = slabOf(altitudeOf(at + w.direction * 0.01));
        majorant = cellMajorants[majorantIndex(tableTexel(ring, local), slab)];  // before slab is converted (docs/building.md)
        float lowest = shellBottom() + float(slab) * slabHeight();
        float2 below = sphereRoots(w.origin, w.direction, frame.planet.x + lowest);
        float2 above = sphereRoots(w.origin, w.direction, frame.planet.x + lowest + slabHeight());
        float past = w.t + 0.005;
        if (below.y >= below.x) {
            if (below.x > past) leave = min(leave, below.x);
            else if (below.y > past) leave = min(leave, below.y);
        }
        if (above.y >= above.x) {
            if (above.x > past) leave = min(leave, above.x);
            else if (above.y > past) leave = min(leave, above.y);
        }
        // Never stand still: a stretch is at least a centimetre (within the twentieth of a cell and
        // the metre each slab's majorant spares).
        leave = min(max(leave, w.t + 0.01), end);
        t0 = w.t;
        t1 = leave;
        w.t = leave;
        if (majorant > 0.0) return true;
    }
    return false;
}

#endif
