// Epipolar sampling, pass 2: each slice's entry and exit points on the screen
// (lightshafts/epipolar_geometry.hlsli, sliceEndpoints).
#include "lightshafts/epipolar_inputs.hlsli"

RWTexture2D<float4> sliceEndsOut : register(u0);

[numthreads(SAMPLE_GROUP, 1, 1)]
void main(uint3 id : SV_DispatchThreadID) {
    if (id.x >= epipolar.sampling.x) return;
    sliceEndsOut[uint2(id.x, 0)] = sliceEndpoints(id.x);
}
