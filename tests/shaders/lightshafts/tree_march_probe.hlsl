// For tests/gpu/EpipolarSamplingTest.cpp: the program's march (lightshafts/ray_march.hlsli, with
// the 1D min/max trees compiled in) of every valid epipolar sample of the last frame, through
// the program's own inputs (lightshafts/epipolar_inputs.hlsli): (lit length D_lit, first lit
// point D_start, marched begin, marched end) per sample, (-1, -1, 0, 0) for invalid ones. The
// test runs it with the trees walked (epipolar.trees.x = 1) and not.
#define FIRMAMENT_NO_SHADE_PIXEL 1
#define FIRMAMENT_MINMAX_TREES 1
#include "lightshafts/epipolar_inputs.hlsli"
#include "atmosphere/yusov/shade_pixel.hlsli"
#include "lightshafts/ray_march.hlsli"

RWStructuredBuffer<float4> results : register(u0);

[numthreads(64, 1, 1)]
void main(uint3 id : SV_DispatchThreadID) {
    if (id.x >= epipolar.sampling.y) return;
    float4 coordinates = sampleCoordinates.Load(int3(id.xy, 0));
    float4 result = float4(-1.0, -1.0, 0.0, 0.0);
    if (validSample(coordinates)) {
        PixelView v = pixelView(coordinates.xy, coordinates.w, 1.0);
        if (v.inAtmosphere) {
            ShadowMarch m = marchShadows(v.ray, frame.directionToSun.xyz, false, id.y);
            result = float4(m.litLength, m.firstLit, m.begin, m.end);
        }
    }
    results[id.y * epipolar.sampling.y + id.x] = result;
}
