// Epipolar sampling, pass 8: the 1D min/max binary trees (lightshafts/minmax_trees.hlsli), one
// per slice and marched cascade, one thread group per tree. Level 0 from the shadow map along
// the slice line; each level above from pairs of the one below, reduced in group-shared memory.
// With the 16-bit format the minima are rounded down and the maxima up, so that the stored
// bounds still hold.
#include "lightshafts/epipolar_inputs.hlsli"
#include "lightshafts/minmax_trees.hlsli"

#define TREE_GROUP 256
static const uint kMaxTreeEntries = 4096;  // the largest cascade resolution

#if MINMAX_UNORM
RWTexture2D<unorm float2> treeOut : register(u0);
#else
RWTexture2D<float2> treeOut : register(u0);
#endif

groupshared float2 levelA[kMaxTreeEntries / 2];
groupshared float2 levelB[kMaxTreeEntries / 4];

// The shadow map's least and greatest depth under the comparison filter anywhere on the line
// between steps k and k + 1 (in atlas texels: the two texels around each position on either
// axis, a quarter texel to spare); (0, 1) where the line leaves the tile, which no walk decides.
float2 leafBounds(float4 sliceLine, uint c, uint k) {
    float2 a = sliceLine.xy + sliceLine.zw * (float)k, b = a + sliceLine.zw;
    if (any(min(a, b) < 0.0) || any(max(a, b) > 1.0)) return float2(0.0, 1.0);
    float2 atlasSize = shadows.map.x * shadows.atlas.xy;
    float2 pa = atlasCoordinates(c, a) * atlasSize, pb = atlasCoordinates(c, b) * atlasSize;
    int2 lo = max((int2)floor(min(pa, pb) - 0.5 - kTreeSlack), 0);
    int2 hi = min((int2)floor(max(pa, pb) - 0.5 + kTreeSlack) + 1, (int2)atlasSize - 1);
    float2 bounds = float2(1.0, 0.0);
    for (int y = lo.y; y <= hi.y; ++y)
        for (int x = lo.x; x <= hi.x; ++x) {
            float depth = shadowMap.Load(int3(x, y, 0));
            bounds = float2(min(bounds.x, depth), max(bounds.y, depth));
        }
#if MINMAX_UNORM
    bounds = float2(floor(bounds.x * 65535.0), ceil(bounds.y * 65535.0)) / 65535.0;
#endif
    return bounds;
}

float2 merge(float2 a, float2 b) {
    return float2(min(a.x, b.x), max(a.y, b.y));
}

[numthreads(TREE_GROUP, 1, 1)]
void main(uint3 group : SV_GroupID, uint3 thread : SV_GroupThreadID) {
    uint row = group.x, slices = epipolar.sampling.x;
    uint c = lightShafts.mode.w + row / slices, slice = row % slices;
    uint entries = treeEntries();
    float4 sliceLine = sliceLines.Load(int3(slice, c, 0));
    bool valid = validSliceLine(sliceLine);
    // Level 0, and level 1 into group-shared memory.
    for (uint k = thread.x; k < entries / 2; k += TREE_GROUP) {
        float2 a = valid ? leafBounds(sliceLine, c, 2 * k) : float2(0.0, 1.0);
        float2 b = valid ? leafBounds(sliceLine, c, 2 * k + 1) : float2(0.0, 1.0);
        treeOut[uint2(2 * k, row)] = a;
        treeOut[uint2(2 * k + 1, row)] = b;
        levelA[k] = merge(a, b);
    }
    GroupMemoryBarrierWithGroupSync();
    // Level L holds `count` entries in levelA (L odd) or levelB (L even); write it, then merge
    // its pairs into the other array.
    uint count = entries / 2;
    bool inA = true;
    for (uint level = 1; count >= 1; ++level) {
        uint offset = levelOffset(level);
        for (uint i = thread.x; i < count; i += TREE_GROUP) treeOut[uint2(offset + i, row)] = inA ? levelA[i] : levelB[i];
        if (count == 1) break;
        for (uint j = thread.x; j < count / 2; j += TREE_GROUP) {
            if (inA) levelB[j] = merge(levelA[2 * j], levelA[2 * j + 1]);
            else levelA[j] = merge(levelB[2 * j], levelB[2 * j + 1]);
        }
        GroupMemoryBarrierWithGroupSync();
        count /= 2;
        inA = !inA;
    }
}
