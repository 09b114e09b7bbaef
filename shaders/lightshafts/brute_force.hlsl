// The light shafts' brute-force reference: every pixel's view ray marched through the shadow
// cascades (lightshafts/ray_march.hlsli), sky and geometry alike, in one pass that replaces the
// atmosphere's Sky and Aerial perspective passes. Over geometry at P: its radiance times
// T(C -> P) plus the light scattered where the sun reaches; where nothing was drawn: that light
// along the whole ray, and the sun's disc through the atmosphere. "Lighting only" leaves the
// scene and the disc out.
#include "atmosphere/atmosphere_structures.hlsli"
#include "common/fullscreen_triangle.hlsli"
#include "lightshafts/lightshaft_structures.hlsli"
#include "shadows/shadow_structures.hlsli"

cbuffer FrameBuffer : register(b0) { FrameConstants frame; };
cbuffer AtmosphereBuffer : register(b1) { AtmosphereConstants atmosphere; };
cbuffer LightShaftBuffer : register(b2) { LightShaftConstants lightShafts; };
cbuffer ShadowBuffer : register(b3) { ShadowConstants shadows; };
cbuffer CloudShadowBuffer : register(b4) { CloudShadowConstants cloudShadow; };

Texture2D<float4> sceneRadiance : register(t0);  // the HDR frame before this pass
Texture2D<float> sceneDepth : register(t1);
Texture2D<float4> netDensityLut : register(t2);
Texture3D<float4> singleScatteringLut : register(t3);
Texture3D<float4> highOrderScatteringLut : register(t4);
Texture3D<float4> multipleScatteringLut : register(t5);
Texture2D<float> shadowMap : register(t6);
Texture2DArray<float4> cloudShadowMap : register(t7);  // the clouds' transparency maps (shadows/cloud_shadow.hlsli)
SamplerState linearClamp : register(s0);
SamplerComparisonState shadowComparison : register(s1);

#define FIRMAMENT_CLOUD_SHADOWS
#include "lightshafts/ray_march.hlsli"

// Only where the sun reaches, times the scattering scale.
float3 scatteredLight(ViewRay ray, float3 sunDir) {
    return shadowedInscattering(ray, sunDir) * lightShafts.march.z;
}

#include "atmosphere/yusov/shade_pixel.hlsli"

FullscreenVertex vs_main(uint vertexId : SV_VertexID) {
    return fullscreenTriangle(vertexId);
}

float4 ps_main(FullscreenVertex input) : SV_Target {
    int2 pixel = int2(input.position.xy);
    float depth = sceneDepth.Load(int3(pixel, 0));
    bool lightingOnly = lightShafts.options.x != 0;
    float3 radiance = depth > 0.0 && !lightingOnly ? sceneRadiance.Load(int3(pixel, 0)).rgb : 0.0;
    return float4(shadePixel(input.uv, depth, radiance, !lightingOnly, lightShafts.sun.xy), 1.0);
}
