// The rasterizer-ordered path's merge (clouds/ordered_blending.hlsli) from the pixel stage: a
// full-screen triangle per draw, each pixel merging one fragment made from its position and
// probe.z, what is pushed behind blended into the target. One fragment per pixel per draw keeps
// the order without the views' ordering, which Wine ignores.
#include "clouds/ordered_blending.hlsli"
#include "common/fullscreen_triangle.hlsli"

cbuffer Probe : register(b0) { uint4 probe; };  // z: the draw

FullscreenVertex vs_main(uint vertexId : SV_VertexID) { return fullscreenTriangle(vertexId); }

float4 ps_main(FullscreenVertex input) : SV_Target {
    uint2 pixel = uint2(input.position.xy);
    ParticleFragment f;
    f.colour = float3(pixel.x + 1, pixel.y + 1, probe.z + 1);
    f.extinction = 0.001 * (probe.z + 1);
    // Draw 0 far, draw 1 overlapping it in front, draw 2 wholly in front, draw 3 wholly behind.
    float fronts[4] = {300.0, 200.0, 50.0, 900.0};
    f.front = fronts[probe.z];
    f.back = f.front + 150.0;
    BlendedLight behind = mergeInPixelOrder(pixel, f);
    return float4(behind.light, 1.0 - behind.transmittance);
}
