// Epipolar sampling, pass 9's end in the cascade-by-cascade modes: each listed sample's parts
// from march_cascades.hlsl added up in cascade order (addCascade, as the single pass adds them),
// and the in-scattering made of the whole (lightshafts/ray_march.hlsli, inscatteringFromMarch).
#define FIRMAMENT_NO_SHADE_PIXEL 1
#include "lightshafts/epipolar_inputs.hlsli"
#include "atmosphere/yusov/shade_pixel.hlsli"
#include "lightshafts/ray_march.hlsli"

cbuffer CascadePassBuffer : register(b5) { CascadePassConstants cascadePass; };
RWTexture2D<float4> marchedOut : register(u0);

[numthreads(LIST_GROUP, 1, 1)]
void main(uint3 id : SV_DispatchThreadID) {
    uint entry, index;
    if (!listEntryAt(id, entry, index)) return;
    uint2 texel = unpackEntry(entry);
    float4 coordinates = sampleCoordinates.Load(int3(texel, 0));
    PixelView v = pixelView(coordinates.xy, coordinates.w, 1.0);
    float3 light = 0.0;
    if (v.inAtmosphere) {
        ShadowMarch m = marchedStretch(v.ray);
        if (m.end > m.begin) {
            uint cascades = shadows.mode.x - lightShafts.mode.w;
            for (uint k = 0; k < cascades; ++k) {
                CascadePartial partial = cascadeParts[k * cascadePass.cascades.y + index];
                CascadeMarch cm;
                cm.litLength = partial.march.x;
                cm.firstLit = partial.march.y;
                cm.singleScattering = partial.scattering.rgb;
                addCascade(m, cm);
            }
        }
        light = inscatteringFromMarch(v.ray, frame.directionToSun.xyz, m);
    }
    marchedOut[texel] = float4(light, 1.0);
}
