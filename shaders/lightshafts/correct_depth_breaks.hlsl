// Epipolar sampling, pass 12: the pixels the unwarping listed (depth breaks, with "Correction
// at depth breaks") ray marched one by one, as the brute-force reference does
// (lightshafts/brute_force.hlsl).
#include "lightshafts/epipolar_inputs.hlsli"
#include "lightshafts/ray_march.hlsli"

// Only where the sun reaches, times the scattering scale.
float3 scatteredLight(ViewRay ray, float3 sunDir) {
    return shadowedInscattering(ray, sunDir) * lightShafts.march.z;
}

#include "atmosphere/yusov/shade_pixel.hlsli"

RWTexture2D<float4> frameOut : register(u0);

[numthreads(LIST_GROUP, 1, 1)]
void main(uint3 id : SV_DispatchThreadID) {
    uint entry;
    if (!listEntry(id, entry)) return;
    uint2 pixel = unpackEntry(entry);
    float depth = sceneDepth.Load(int3(pixel, 0));
    bool lightingOnly = lightShafts.options.x != 0;
    float3 radiance = depth > 0.0 && !lightingOnly ? sceneRadiance.Load(int3(pixel, 0)).rgb : 0.0;
    float2 uv = ((float2)pixel + 0.5) * frame.screen.zw;
    frameOut[pixel] = float4(shadePixel(uv, depth, radiance, !lightingOnly, lightShafts.sun.xy), 1.0);
}
