#ifndef FIRMAMENT_LIGHTSHAFTS_MINMAX_TREES_HLSLI
#define FIRMAMENT_LIGHTSHAFTS_MINMAX_TREES_HLSLI
// 1D min/max binary trees (Yusov 2013, "1D min/max binary trees"; Yusov's GPU Pro 5 chapter).
// Every view ray of an epipolar slice projects, in a cascade's shadow map, onto one half-line
// from the camera's place (the slice line, pass 7). The shadow map's depths along that line form
// a 1D array; a binary tree of minima and maxima over it tells, for a stretch of a ray, whether
// the ray's depth lies above every occluder there (uniformly lit), below every occluder (uniformly
// shadowed), or neither. The march then takes whole stretches at once and samples the shadow map
// only where the tree cannot decide.
//
// Layout (`minMaxTree`, one row per slice and marched cascade, row = (cascade - first) x slices
// + slice): level 0 holds E entries at columns [0, E), level L the E / 2^L entries from column
// 2E - 2E / 2^L. Entry k of level 0 bounds every shadow-map texel that the bilinear comparison
// filter reads anywhere on the line between steps k and k + 1 (with a quarter texel to spare), so
// the tree is conservative: where it says lit or shadowed, every filtered tap would say the same.
// E is the cascade's resolution: one step is a texel along the line's major axis, so E steps
// cross the tile.
//
// The includer declares the cbuffers `shadows`, `lightShafts` and `epipolar`,
// Texture2D<float4> sliceLines (slices x cascades) and Texture2D<float2> minMaxTree.
#include "shadows/cascade_sampling.hlsli"

static const float4 kNoSliceLine = float4(-1.0e4, -1.0e4, 0.0, 0.0);
static const float kTreeSlack = 0.25;  // texels

bool validSliceLine(float4 sliceLine) {
    return sliceLine.x > -1.0e3;
}

// The slice line in cascade c of a slice whose exit point is ends.zw: (origin u, v; step u, v).
float4 sliceLine(float4 ends, uint c) {
    float res = shadows.map.x;
    float4 farPoint = mul(frame.clipToDirection, float4(ends.zw, 1.0, 1.0));
    float3 viewDir = normalize(farPoint.xyz / farPoint.w);
    // The shadow map's projection is orthographic along the sun: a direction moves (u, v) by its
    // linear part alone, and the sun's own direction not at all.
    float2 direction = mul(shadows.worldToShadow[c], float4(viewDir, 0.0)).xy;
    float major = max(abs(direction.x), abs(direction.y));
    float2 step = major > 1e-12 ? direction / (major * res) : float2(1.0 / res, 0.0);
    float2 origin = shadowMapCoordinates(c, frame.cameraPosition.xyz).xy;
    if (any(origin < 0.0) || any(origin > 1.0)) {
        // Move to where the half-line enters the tile (the slab method), if it does.
        float2 safe = abs(step) < 1e-12 ? 1e-12 : step;
        float2 k0 = (0.0 - origin) / safe, k1 = (1.0 - origin) / safe;
        float kNear = max(max(min(k0.x, k1.x), min(k0.y, k1.y)), 0.0);
        float kFar = min(max(k0.x, k1.x), max(k0.y, k1.y));
        if (kNear > kFar) return kNoSliceLine;
        origin += step * kNear;
    }
    return float4(origin, step);
}

// Where a point of the tile lies along the line, in steps.
float lineParameter(float4 sliceLine, float2 uv) {
    return dot(uv - sliceLine.xy, sliceLine.zw) / dot(sliceLine.zw, sliceLine.zw);
}

uint treeEntries() { return epipolar.trees.y; }
uint levelOffset(uint level) { return 2 * treeEntries() - (2 * treeEntries() >> level); }

// A march's walk along the tree of one slice in one cascade: the march's steps (steps of equal
// length from uvz0 to uvz1) in line parameters and depths.
struct TreeWalk {
    bool valid;
    uint row;
    float tA, dt;        // step i's middle lies at tA + (i + 0.5) dt
    float zA, dzdt;      // the ray's depth at line parameter t: zA + (t - tA') dzdt, tA' = tA
    float tMin, tMax;    // the marched stretch's line parameters
};

TreeWalk beginTreeWalk(uint c, uint slice, float3 uvz0, float3 uvz1, uint steps) {
    TreeWalk w;
    w.valid = false;
    w.row = (c - lightShafts.mode.w) * epipolar.sampling.x + slice;
    w.tA = 0.0;
    w.dt = 0.0;
    w.zA = uvz0.z;
    w.dzdt = 0.0;
    w.tMin = 0.0;
    w.tMax = 0.0;
    if (epipolar.trees.x == 0) return w;
    float4 sliceLine = sliceLines.Load(int3(slice, c, 0));
    if (!validSliceLine(sliceLine)) return w;
    float t0 = lineParameter(sliceLine, uvz0.xy), t1 = lineParameter(sliceLine, uvz1.xy);
    w.valid = true;
    w.tA = t0;
    w.dt = (t1 - t0) / (float)steps;
    w.dzdt = abs(t1 - t0) > 1e-6 ? (uvz1.z - uvz0.z) / (t1 - t0) : 0.0;
    w.tMin = min(t0, t1);
    w.tMax = max(t0, t1);
    return w;
}

// What node (level, index) says of the ray over its stretch of the line: 1 lit, 0 shadowed,
// -1 undecided (an occluder's depth within the ray's there, or the ray leaving the depth range).
float classifyNode(TreeWalk w, uint level, uint index) {
    float2 bounds = minMaxTree.Load(int3(levelOffset(level) + index, w.row, 0));
    float size = (float)(1u << level);
    float t0 = clamp((float)index * size, w.tMin, w.tMax), t1 = clamp((float)(index + 1) * size, w.tMin, w.tMax);
    float z0 = w.zA + (t0 - w.tA) * w.dzdt, z1 = w.zA + (t1 - w.tA) * w.dzdt;
    float zNear = min(z0, z1) - shadows.map.z, zFar = max(z0, z1) - shadows.map.z;
    if (min(z0, z1) < 0.0 || max(z0, z1) > 1.0) return -1.0;
    if (zFar <= bounds.x) return 1.0;
    if (zNear > bounds.y) return 0.0;
    return -1.0;
}

// The visibility the tree proves for step i and the steps after it in the same node (`run`
// steps in all, at least 1); -1 where it proves nothing (the march then samples the map).
float walkTree(TreeWalk w, uint i, uint steps, out uint run) {
    run = 1;
    if (!w.valid || w.dt <= 0.0) return -1.0;
    float t = w.tA + ((float)i + 0.5) * w.dt;
    if (t < 0.0 || t >= (float)treeEntries()) return -1.0;
    uint index = (uint)t, level = 0;
    float state = classifyNode(w, 0, index);
    if (state < 0.0) return -1.0;
    uint top = epipolar.trees.z;
    while (level < top && classifyNode(w, level + 1, index >> 1) == state) {
        ++level;
        index >>= 1;
    }
    // The steps whose middles lie before the node's end.
    float end = (float)((index + 1) << level);
    float last = ceil((end - w.tA) / w.dt - 0.5);
    run = (uint)clamp(last - (float)i, 1.0, (float)(steps - i));
    return state;
}

#endif
