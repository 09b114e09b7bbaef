// Epipolar sampling, pass 10: every sample's in-scattering from its two sources along its slice
// (a marched sample is its own).
//
// What is interpolated is the share of the unshadowed in-scattering that the march found, not
// the in-scattering itself: L(i) = L_u(i) x lerp(L(left) / L_u(left), L(right) / L_u(right)),
// with L_u the unshadowed in-scattering pass 4 computed at every sample (coarse_inscattering.hlsl).
// Yusov 2013 interpolates L linearly. The sky's light is not linear over the initial step (a
// sixteenth of the slice at the defaults: several degrees of view, whatever the resolution) and its
// neighbours differ by far less than the refinement threshold, so nothing refines there: with L
// interpolated, the open sky by Integration came out up to 2.8% to 3.8% off the CPU reference,
// where the per-pixel sky is 1.0% to 1.4% off (docs/lightshafts.md, pass 10). With the share
// interpolated, an unshadowed sample gets exactly the per-pixel value, and a shadow's edge
// between two sources is interpolated as before.
#include "lightshafts/epipolar_inputs.hlsli"

RWTexture2D<float4> interpolatedOut : register(u0);

// The share of its unshadowed light a sample receives, per channel: 1 where there is no
// unshadowed light to share.
float3 litShare(float3 marched, float3 unshadowed) {
    return unshadowed > 1e-30 ? marched / max(unshadowed, 1e-30) : 1.0;
}

[numthreads(SAMPLE_GROUP, 1, 1)]
void main(uint3 id : SV_DispatchThreadID) {
    if (id.x >= epipolar.sampling.y) return;
    uint2 sources = interpolationSources.Load(int3(id.xy, 0));
    float3 light = 0.0;
    if (sources.x != kNoSource) {
        // The loads come before any float conversion of the indices: vkd3d-compiler 2.1 converted
        // `sources` in place and then loaded at the converted values (docs/building.md).
        float3 left = marchedInscattering.Load(int3(sources.x, id.y, 0)).rgb;
        float3 right = marchedInscattering.Load(int3(sources.y, id.y, 0)).rgb;
        float3 leftUnshadowed = coarseInscattering.Load(int3(sources.x, id.y, 0)).rgb;
        float3 rightUnshadowed = coarseInscattering.Load(int3(sources.y, id.y, 0)).rgb;
        float3 unshadowed = coarseInscattering.Load(int3(id.xy, 0)).rgb;
        int offset = (int)id.x - (int)sources.x, span = max((int)sources.y - (int)sources.x, 1);
        float t = (float)offset / (float)span;
        light = unshadowed * lerp(litShare(left, leftUnshadowed), litShare(right, rightUnshadowed), t);
    }
    interpolatedOut[id.xy] = float4(light, 1.0);
}
