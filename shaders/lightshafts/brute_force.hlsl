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

Texture2D<float4> sceneRadiance : register(t0);  // the HDR frame before this pass
Texture2D<float> sceneDepth : register(t1);
Texture2D<float4> netDensityLut : register(t2);
Texture3D<float4> singleScatteringLut : register(t3);
Texture3D<float4> highOrderScatteringLut : register(t4);
Texture3D<float4> multipleScatteringLut : register(t5);
Texture2D<float> shadowMap : register(t6);
SamplerState linearClamp : register(s0);
SamplerComparisonState shadowComparison : register(s1);

#include "lightshafts/ray_march.hlsli"

FullscreenVertex vs_main(uint vertexId : SV_VertexID) {
    return fullscreenTriangle(vertexId);
}

float4 ps_main(FullscreenVertex input) : SV_Target {
    int2 pixel = int2(input.position.xy);
    float depth = sceneDepth.Load(int3(pixel, 0));
    bool geometry = depth > 0.0;  // reversed Z: 0 is the far plane, where nothing was drawn
    bool lightingOnly = lightShafts.options.x != 0;
    float3 radiance = geometry && !lightingOnly ? sceneRadiance.Load(int3(pixel, 0)).rgb : 0.0;
    float2 ndc = float2(input.uv.x * 2.0 - 1.0, 1.0 - input.uv.y * 2.0);
    float4 farPoint = mul(frame.clipToDirection, float4(ndc, 1.0, 1.0));
    float3 viewDir = normalize(farPoint.xyz / farPoint.w);
    float3 sunDir = frame.directionToSun.xyz;
    float3 earthCentre = float3(0.0, -atmosphere.earth.x, 0.0);

    ViewRay ray;
    ray.camera = frame.cameraPosition.xyz;
    ray.start = frame.cameraPosition.xyz - earthCentre;
    ray.viewDir = viewDir;
    bool inAtmosphere = clipRayToAtmosphere(atmosphere, ray.start, viewDir, ray.offset);
    float geometryDistance = 0.0;
    if (geometry) {
        float4 world = mul(frame.inverseViewProjection, float4(ndc, depth, 1.0));
        geometryDistance = length(world.xyz / world.w - frame.cameraPosition.xyz) - ray.offset;
    }
    bool sunHere = !geometry && !lightingOnly && dot(viewDir, sunDir) > lightShafts.sun.x;
    if (!inAtmosphere || (geometry && geometryDistance <= 0.0)) {
        // Outside the atmosphere: geometry and the sun as they are, space is black.
        bool sunSeen = sunHere && !rayHitsGround(atmosphere, frame.cameraPosition.xyz - earthCentre, viewDir);
        return float4(geometry ? radiance : (sunSeen ? frame.sunIrradiance.rgb * lightShafts.sun.y : 0.0), 1.0);
    }
    ray.hitsGround = rayHitsGround(atmosphere, ray.start, viewDir);
    float toEnd = rayLengthInAtmosphere(atmosphere, ray.start, viewDir, ray.hitsGround);
    // Geometry on the ground lies where the ray meets the Earth: clamped to the ray's end.
    ray.length = geometry ? min(geometryDistance, toEnd) : toEnd;
    ray.endsAtBoundary = !geometry;

    float3 light = frame.sunIrradiance.rgb * shadowedInscattering(ray, sunDir);
    if (geometry) return float4(radiance * transmittanceTo(ray, ray.length) + light, 1.0);
    if (sunHere && !ray.hitsGround) {
        float h = length(ray.start) - atmosphere.earth.x;
        light += frame.sunIrradiance.rgb * lightShafts.sun.y *
                 sunTransmittance(atmosphere, netDensityLut, linearClamp, h, dot(normalize(ray.start), viewDir));
    }
    return float4(light, 1.0);
}
