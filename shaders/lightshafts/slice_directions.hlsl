// Epipolar sampling, pass 7: each slice's line in each cascade's shadow map. The view rays of a
// slice lie in one plane with the direction to the sun; the sun's orthographic projection
// flattens that plane onto a half-line from the camera's place in the shadow map (Yusov 2013,
// "1D min/max binary trees"). Texel (slice, cascade): xy the origin in the cascade's tile (u, v),
// zw the step along the line, one texel along its major axis. Where the camera's place lies
// outside the tile, the origin moves to where the line enters it; a line that misses the tile,
// or a slice that is invalid, gets kNoSliceLine.
#include "lightshafts/epipolar_inputs.hlsli"
#include "lightshafts/minmax_trees.hlsli"

RWTexture2D<float4> sliceLinesOut : register(u0);

[numthreads(SAMPLE_GROUP, 1, 1)]
void main(uint3 id : SV_DispatchThreadID) {
    uint slice = id.x, cascade = id.y;
    if (slice >= epipolar.sampling.x) return;
    float4 ends = sliceEnds.Load(int3(slice, 0, 0));
    sliceLinesOut[id.xy] = validSlice(ends) ? sliceLine(ends, cascade) : kNoSliceLine;
}
