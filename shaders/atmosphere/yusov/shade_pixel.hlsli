#ifndef FIRMAMENT_YUSOV_SHADE_PIXEL_HLSLI
#define FIRMAMENT_YUSOV_SHADE_PIXEL_HLSLI
// A pixel seen through Yusov 2013's atmosphere, for the passes that draw it: the atmosphere's
// (atmosphere/yusov/render.hlsl) and the light shafts' (lightshafts/brute_force.hlsl and the
// epipolar passes).
//  - Over geometry at P: its radiance times T(C -> P), plus the light scattered in between.
//  - Where nothing was drawn: the light scattered along the whole ray, and the sun's disc
//    attenuated by the atmosphere where the ground does not hide it.
//  - A camera above the atmosphere starts its rays where they enter it; space is black.
// The includer declares cbuffer `frame` (FrameConstants) besides view_ray.hlsli's inputs.
// shadePixel() also needs, defined before this file is included,
//     float3 scatteredLight(ViewRay ray, float3 sunDir)
// the light scattered into the ray per unit sun irradiance (all of it, or where the sun
// reaches); an includer that finds that light another way (interpolated from epipolar
// samples) defines FIRMAMENT_NO_SHADE_PIXEL and uses pixelView() and composePixel().
#include "atmosphere/yusov/view_ray.hlsli"

// What a pixel looks at.
struct PixelView {
    ViewRay ray;
    bool inAtmosphere;  // the ray crosses some atmosphere before what was drawn
    bool geometry;      // something was drawn (depth > 0)
    bool sunSeen;       // the sun's disc: looked at, nothing drawn there, the ground not in the way
};

float2 ndcOf(float2 uv) {
    return float2(uv.x * 2.0 - 1.0, 1.0 - uv.y * 2.0);
}

// The view ray through `ndc` that ends at the scene's depth there (reversed Z, 0 where nothing
// was drawn); cosSun: the cosine of the sun's angular radius.
PixelView pixelView(float2 ndc, float depth, float cosSun) {
    float4 farPoint = mul(frame.clipToDirection, float4(ndc, 1.0, 1.0));
    float3 viewDir = normalize(farPoint.xyz / farPoint.w);
    float3 earthCentre = float3(0.0, -atmosphere.earth.x, 0.0);

    PixelView v;
    v.ray.camera = frame.cameraPosition.xyz;
    v.ray.start = frame.cameraPosition.xyz - earthCentre;
    v.ray.viewDir = viewDir;
    v.ray.offset = 0.0;
    v.ray.length = 0.0;
    v.ray.hitsGround = false;
    v.ray.endsAtBoundary = depth <= 0.0;
    v.inAtmosphere = clipRayToAtmosphere(atmosphere, v.ray.start, viewDir, v.ray.offset);
    v.geometry = depth > 0.0;
    float geometryDistance = 0.0;
    if (v.geometry) {
        float4 world = mul(frame.inverseViewProjection, float4(ndc, depth, 1.0));
        geometryDistance = length(world.xyz / world.w - frame.cameraPosition.xyz) - v.ray.offset;
    }
    bool sunHere = !v.geometry && dot(viewDir, frame.directionToSun.xyz) > cosSun;
    if (!v.inAtmosphere || (v.geometry && geometryDistance <= 0.0)) {
        v.inAtmosphere = false;
        v.sunSeen = sunHere && !rayHitsGround(atmosphere, frame.cameraPosition.xyz - earthCentre, viewDir);
        return v;
    }
    v.ray.hitsGround = rayHitsGround(atmosphere, v.ray.start, viewDir);
    float toEnd = rayLengthInAtmosphere(atmosphere, v.ray.start, viewDir, v.ray.hitsGround);
    // Geometry on the ground lies where the ray meets the Earth: a comparison would be decided
    // by rounding pixel by pixel, so the distance is clamped to the ray's end.
    v.ray.length = v.geometry ? min(geometryDistance, toEnd) : toEnd;
    v.sunSeen = sunHere && !v.ray.hitsGround;
    return v;
}

// The pixel's radiance from the scene's `radiance`, the scattered `light` (times the sun's
// irradiance) and the transmittance to the geometry; showSun: the disc is drawn, sunRadiance
// its radiance per unit irradiance.
float3 composePixel(PixelView v, float3 radiance, float3 light, float3 transmittance, bool showSun, float sunRadiance) {
    bool disc = showSun && v.sunSeen;
    // Outside the atmosphere: geometry and the sun as they are, space is black.
    if (!v.inAtmosphere) return v.geometry ? radiance : (disc ? frame.sunIrradiance.rgb * sunRadiance : 0.0);
    if (v.geometry) return radiance * transmittance + light;
    if (disc) {
        float h = length(v.ray.start) - atmosphere.earth.x;
        light += frame.sunIrradiance.rgb * sunRadiance *
                 sunTransmittance(atmosphere, netDensityLut, linearClamp, h, dot(normalize(v.ray.start), v.ray.viewDir));
    }
    return light;
}

#ifndef FIRMAMENT_NO_SHADE_PIXEL
// uv: the pixel's centre in [0, 1]; depth: the scene's (reversed Z, 0 where nothing was drawn);
// radiance: what the scene drew there; showSun: the sun's disc is drawn; sun: x the cosine of
// its angular radius, y its radiance per unit irradiance.
float3 shadePixel(float2 uv, float depth, float3 radiance, bool showSun, float2 sun) {
    PixelView v = pixelView(ndcOf(uv), depth, sun.x);
    if (!v.inAtmosphere) return composePixel(v, radiance, 0.0, 1.0, showSun, sun.y);
    float3 light = frame.sunIrradiance.rgb * scatteredLight(v.ray, frame.directionToSun.xyz);
    return composePixel(v, radiance, light, v.geometry ? transmittanceTo(v.ray, v.ray.length) : 1.0, showSun, sun.y);
}
#endif

#endif
