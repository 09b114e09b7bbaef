// "Shafts from clouds: shadow map" (Yusov 2014's sample; docs/clouds.md, "Shadows and shafts
// from clouds"): the clouds' light-space map drawn into one shadow cascade as casters, so that
// the light shafts' march and their 1D min/max trees see the clouds as they see the terrain. A
// full-screen triangle over the cascade's tile: each texel's sun ray is found in the cloud map,
// and where the clouds let through less than half of the light, the middle of their stretch on
// that ray is written as the texel's depth (the depth test keeps whichever is nearer the sun,
// terrain or cloud). Binary: the transparency map mode keeps the clouds' partial transmittance.
#define FIRMAMENT_CLOUD_SHADOW_WRITER
#include "clouds/cloud_structures.hlsli"
#include "common/fullscreen_triangle.hlsli"
#include "shadows/shadow_structures.hlsli"

cbuffer CloudShadowBuffer : register(b0) { CloudShadowConstants cloudShadow; };
cbuffer MergeBuffer : register(b1) { CloudShadowMergeConstants merge; };
Texture2DArray<float4> cloudShadowMap : register(t0);
#include "shadows/cloud_shadow.hlsli"

// Below this transmittance a cloud is a caster.
static const float kOpaqueBelow = 0.5;

FullscreenVertex vs_main(uint vertexId : SV_VertexID) {
    return fullscreenTriangle(vertexId);
}

float ps_main(FullscreenVertex input) : SV_Depth {
    float2 ndc = float2(input.uv.x * 2.0 - 1.0, 1.0 - input.uv.y * 2.0);
    float4 point4 = mul(merge.clipToWorld, float4(ndc, 0.5, 1.0));
    float3 world = point4.xyz / point4.w;
    // The near map where it reaches, else the far one.
    uint slice = 0;
    float2 p = cloudShadowPositionIn(0, world);
    if (any(abs(p) >= 1.0)) {
        slice = 1;
        p = cloudShadowPositionIn(1, world);
        if (any(abs(p) >= 1.0)) discard;
    }
    int n = int(cloudShadow.right.w);
    int2 texel = clamp(int2(floor(cloudShadowTexel(p))), 0, n - 1);
    float4 clouds = cloudShadowMap.Load(int4(texel, slice, 0));
    if (clouds.a >= kOpaqueBelow) discard;
    float middle = 0.5 * (clouds.r - clouds.g);
    float3 caster = world + cloudShadow.sun.xyz * (middle - cloudShadowHeightIn(slice, world));
    float4 clip = mul(merge.worldToClip, float4(caster, 1.0));
    return saturate(clip.z / clip.w);
}
