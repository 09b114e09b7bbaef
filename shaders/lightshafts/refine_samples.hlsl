// Epipolar sampling, pass 5: which samples are ray marched and where every other sample takes
// its in-scattering from (Yusov 2013, "Epipolar sampling"; Yusov's GPU Pro 5 chapter). One
// thread group per slice.
//  - Ray-marching samples are placed every "initial sample step" samples along the slice (the
//    step divided by the epipole sampling density near the epipole, where the light varies
//    fastest), and at the last sample.
//  - Neighbours i and i + 1 are alike when the criterion differs by less than the threshold:
//    camera-space depth relative to the larger (against a fifth of the threshold, as in Intel's
//    sample), or each colour of the coarse in-scattering
//    relative to the larger (never less than a floor, so that the dark sky does not refine
//    everywhere). Where neighbours between two initial samples are not alike, the samples on
//    both sides of the break are marched too.
//  - Every other sample is interpolated from the nearest samples on its slice, left and right,
//    that it reaches without crossing a break: its two interpolation sources. A marched sample
//    is its own source; an invalid one has kNoSource.
#include "lightshafts/epipolar_inputs.hlsli"

#define REFINE_GROUP 128
static const uint kMaxSamples = 2048;

RWTexture2D<uint2> sourcesOut : register(u0);

groupshared uint alike[kMaxSamples];  // alike[i]: samples i and i + 1 are alike

bool samplesAlike(uint i, uint slice) {
    if (i + 1 >= epipolar.sampling.y) return false;
    float4 a = sampleCoordinates.Load(int3(i, slice, 0));
    float4 b = sampleCoordinates.Load(int3(i + 1, slice, 0));
    if (!validSample(a) || !validSample(b)) return false;
    float threshold = epipolar.refinement.x;
    if (epipolar.options.x == 0) return abs(a.z - b.z) / max(max(a.z, b.z), 1.0) < epipolar.refinement.z;
    float3 la = coarseInscattering.Load(int3(i, slice, 0)).rgb;
    float3 lb = coarseInscattering.Load(int3(i + 1, slice, 0)).rgb;
    return all(abs(la - lb) / max(max(la, lb), epipolar.refinement.y) < threshold);
}

uint2 sourcesOf(uint i, uint slice) {
    uint samples = epipolar.sampling.y;
    float4 ends = sliceEnds.Load(int3(slice, 0, 0));
    if (!validSample(sampleCoordinates.Load(int3(i, slice, 0)))) return kNoSource;
    uint step = epipolar.sampling.z;
    uint first = (i / step) * step;
    if (nearEpipole(samplePosition(ends, first))) {
        step = max(step / epipolar.sampling.w, 1u);
        first = (i / step) * step;
    }
    uint last = min(first + step, samples - 1);
    if (i == first || i == last) return i;
    uint left = i, right = i;
    while (left > first && alike[left - 1] != 0) --left;
    while (right < last && alike[right] != 0) ++right;
    if (left == i || right == i) return i;  // next to a break: marched
    return uint2(left, right);
}

[numthreads(REFINE_GROUP, 1, 1)]
void main(uint3 group : SV_GroupID, uint3 thread : SV_GroupThreadID) {
    uint slice = group.x, samples = epipolar.sampling.y;
    for (uint i = thread.x; i < samples; i += REFINE_GROUP) alike[i] = samplesAlike(i, slice) ? 1 : 0;
    GroupMemoryBarrierWithGroupSync();
    for (uint j = thread.x; j < samples; j += REFINE_GROUP) sourcesOut[uint2(j, slice)] = sourcesOf(j, slice);
}
