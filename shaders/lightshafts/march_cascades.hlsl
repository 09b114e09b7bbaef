// Epipolar sampling, pass 9 cascade by cascade ("Cascade processing mode": multi pass, one
// dispatch per cascade; or multi pass instanced, one dispatch whose third group coordinate is
// the cascade): each thread marches one listed sample's ray through one cascade
// (lightshafts/ray_march.hlsli, marchCascade) and stores that cascade's part, which
// combine_cascades.hlsl then adds up. Yusov's sample blends the cascades' passes into one
// target; here each cascade's part is kept and combined in order, which gives the single pass's
// result exactly.
#define FIRMAMENT_NO_SHADE_PIXEL 1
#define FIRMAMENT_MINMAX_TREES 1
#include "lightshafts/epipolar_inputs.hlsli"
#include "atmosphere/yusov/shade_pixel.hlsli"
#include "lightshafts/ray_march.hlsli"

cbuffer CascadePassBuffer : register(b5) { CascadePassConstants cascadePass; };
RWStructuredBuffer<CascadePartial> partialsOut : register(u0);

[numthreads(LIST_GROUP, 1, 1)]
void main(uint3 id : SV_DispatchThreadID) {
    uint entry, index;
    if (!listEntryAt(id, entry, index)) return;
    uint2 texel = unpackEntry(entry);
    uint k = cascadePass.cascades.x + id.z, c = lightShafts.mode.w + k;
    float4 coordinates = sampleCoordinates.Load(int3(texel, 0));
    PixelView v = pixelView(coordinates.xy, coordinates.w, 1.0);
    CascadeMarch cm;
    cm.litLength = 0.0;
    cm.firstLit = -1.0;
    cm.singleScattering = 0.0;
    if (v.inAtmosphere && c < shadows.mode.x) {
        ShadowMarch m = marchedStretch(v.ray);
        if (m.end > m.begin)
            cm = marchCascade(v.ray, frame.directionToSun.xyz, lightShafts.mode.x == kSingleScatteringIntegration, texel.y, c, m.begin, m.end);
    }
    CascadePartial partial;
    partial.march = float4(cm.litLength, cm.firstLit, 0.0, 0.0);
    partial.scattering = float4(cm.singleScattering, 0.0);
    partialsOut[k * cascadePass.cascades.y + index] = partial;
}
