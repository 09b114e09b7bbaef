// Epipolar sampling, pass 9: the listed samples' view rays marched through the shadow cascades
// (lightshafts/ray_march.hlsli, the brute-force reference's march), per unit sun irradiance,
// walking their slice's 1D min/max trees where they were built (1D min/max optimization).
#define FIRMAMENT_NO_SHADE_PIXEL 1
#define FIRMAMENT_MINMAX_TREES 1
#include "lightshafts/epipolar_inputs.hlsli"
#include "atmosphere/yusov/shade_pixel.hlsli"
#include "lightshafts/ray_march.hlsli"

RWTexture2D<float4> marchedOut : register(u0);

[numthreads(LIST_GROUP, 1, 1)]
void main(uint3 id : SV_DispatchThreadID) {
    uint entry;
    if (!listEntry(id, entry)) return;
    uint2 texel = unpackEntry(entry);
    float4 coordinates = sampleCoordinates.Load(int3(texel, 0));
    PixelView v = pixelView(coordinates.xy, coordinates.w, 1.0);
    float3 light = v.inAtmosphere ? shadowedInscatteringInSlice(v.ray, frame.directionToSun.xyz, texel.y) : 0.0;
    marchedOut[texel] = float4(light, 1.0);
}
