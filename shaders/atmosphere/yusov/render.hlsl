// Yusov 2013's atmosphere at render time, without light shafts ("Enable light scattering" on,
// "Enable light shafts" off), as two passes over the frame:
//  - ps_sky, where nothing was drawn (depth 0, the far plane): the sky, L(C, v) times the sun's
//    irradiance, and the sun's disc attenuated by the atmosphere where the ground does not hide it;
//  - ps_aerial_perspective, over geometry at P: its radiance times T(C -> P), plus the light
//    scattered in between, L(C, v) - T(C -> P) L(P, v) (eq. 8). The light shafts replace it.
// Single scattering comes from the table, from numerical integration along the ray (the
// reference the table is measured against), or not at all; the higher orders from the
// high-order table. Without light shafts nothing is occluded, so Occluded differs from
// Unoccluded only with single scattering from the table: then the multiple scattering table
// gives all orders in one look-up (docs/atmosphere.md, "Render modes").
#include "atmosphere/render_passes.hlsli"

cbuffer YusovPassBuffer : register(b2) {
    YusovPassConstants scattering;
};

Texture2D<float4> netDensityLut : register(t2);
Texture3D<float4> singleScatteringLut : register(t3);
Texture3D<float4> highOrderScatteringLut : register(t4);
Texture3D<float4> multipleScatteringLut : register(t5);

#include "atmosphere/yusov/view_ray.hlsli"

// Everything the modes scatter into the ray: nothing is occluded without light shafts.
float3 scatteredLight(ViewRay ray, float3 sunDir) {
    return scatteringAlongRay(ray, sunDir, scattering.mode.x, scattering.mode.z, (int)scattering.mode.y);
}

#include "atmosphere/yusov/shade_pixel.hlsli"

float4 ps_sky(FullscreenVertex input) : SV_Target {
    float depth = sceneDepth.Load(int3(int2(input.position.xy), 0));
    if (depth > 0.0) discard;  // reversed Z: geometry, the other pass's
    return float4(shadePixel(input.uv, depth, 0.0, true, scattering.sun.xy), 1.0);
}

float4 ps_aerial_perspective(FullscreenVertex input) : SV_Target {
    int2 pixel = int2(input.position.xy);
    float depth = sceneDepth.Load(int3(pixel, 0));
    if (depth <= 0.0) discard;  // nothing drawn: the sky pass's
    return float4(shadePixel(input.uv, depth, sceneRadiance.Load(int3(pixel, 0)).rgb, true, scattering.sun.xy), 1.0);
}
