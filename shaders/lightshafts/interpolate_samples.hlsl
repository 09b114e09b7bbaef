// Epipolar sampling, pass 10: every sample's in-scattering, linearly interpolated along its
// slice between its two sources (a marched sample is its own).
#include "lightshafts/epipolar_inputs.hlsli"

RWTexture2D<float4> interpolatedOut : register(u0);

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
        int offset = (int)id.x - (int)sources.x, span = max((int)sources.y - (int)sources.x, 1);
        light = lerp(left, right, (float)offset / (float)span);
    }
    interpolatedOut[id.xy] = float4(light, 1.0);
}
