#ifndef FIRMAMENT_YUSOV_SHADE_PIXEL_HLSLI
#define FIRMAMENT_YUSOV_SHADE_PIXEL_HLSLI
// A pixel seen through Yusov 2013's atmosphere, for the passes that draw it: the atmosphere's
// (atmosphere/yusov/render.hlsl) and the light shafts' (lightshafts/brute_force.hlsl).
//  - Over geometry at P: its radiance times T(C -> P), plus the light scattered in between.
//  - Where nothing was drawn: the light scattered along the whole ray, and the sun's disc
//    attenuated by the atmosphere where the ground does not hide it.
//  - A camera above the atmosphere starts its rays where they enter it; space is black.
// The includer declares cbuffer `frame` (FrameConstants) besides view_ray.hlsli's inputs, and
// defines, before including this file,
//     float3 scatteredLight(ViewRay ray, float3 sunDir)
// the light scattered into the ray per unit sun irradiance (all of it, or where the sun reaches).
#include "atmosphere/yusov/view_ray.hlsli"

// uv: the pixel's centre in [0, 1]; depth: the scene's (reversed Z, 0 where nothing was drawn);
// radiance: what the scene drew there; showSun: the sun's disc is drawn; sun: x the cosine of
// its angular radius, y its radiance per unit irradiance.
float3 shadePixel(float2 uv, float depth, float3 radiance, bool showSun, float2 sun) {
    float2 ndc = float2(uv.x * 2.0 - 1.0, 1.0 - uv.y * 2.0);
    float4 farPoint = mul(frame.clipToDirection, float4(ndc, 1.0, 1.0));
    float3 viewDir = normalize(farPoint.xyz / farPoint.w);
    float3 sunDir = frame.directionToSun.xyz;
    float3 earthCentre = float3(0.0, -atmosphere.earth.x, 0.0);

    ViewRay ray;
    ray.camera = frame.cameraPosition.xyz;
    ray.start = frame.cameraPosition.xyz - earthCentre;
    ray.viewDir = viewDir;
    bool inAtmosphere = clipRayToAtmosphere(atmosphere, ray.start, viewDir, ray.offset);
    bool geometry = depth > 0.0;
    float geometryDistance = 0.0;
    if (geometry) {
        float4 world = mul(frame.inverseViewProjection, float4(ndc, depth, 1.0));
        geometryDistance = length(world.xyz / world.w - frame.cameraPosition.xyz) - ray.offset;
    }
    bool sunHere = showSun && !geometry && dot(viewDir, sunDir) > sun.x;
    if (!inAtmosphere || (geometry && geometryDistance <= 0.0)) {
        // Outside the atmosphere: geometry and the sun as they are, space is black.
        bool sunSeen = sunHere && !rayHitsGround(atmosphere, frame.cameraPosition.xyz - earthCentre, viewDir);
        return geometry ? radiance : (sunSeen ? frame.sunIrradiance.rgb * sun.y : 0.0);
    }
    ray.hitsGround = rayHitsGround(atmosphere, ray.start, viewDir);
    float toEnd = rayLengthInAtmosphere(atmosphere, ray.start, viewDir, ray.hitsGround);
    // Geometry on the ground lies where the ray meets the Earth: a comparison would be decided
    // by rounding pixel by pixel, so the distance is clamped to the ray's end.
    ray.length = geometry ? min(geometryDistance, toEnd) : toEnd;
    ray.endsAtBoundary = !geometry;

    float3 light = frame.sunIrradiance.rgb * scatteredLight(ray, sunDir);
    if (geometry) return radiance * transmittanceTo(ray, ray.length) + light;
    if (sunHere && !ray.hitsGround) {
        float h = length(ray.start) - atmosphere.earth.x;
        light += frame.sunIrradiance.rgb * sun.y * sunTransmittance(atmosphere, netDensityLut, linearClamp, h, dot(normalize(ray.start), viewDir));
    }
    return light;
}

#endif
