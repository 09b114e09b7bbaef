#ifndef FIRMAMENT_CLOUD_ATMOSPHERE_HLSLI
#define FIRMAMENT_CLOUD_ATMOSPHERE_HLSLI
// The atmosphere as the clouds see it, through the tables of the model drawn (CLOUD_ATMOSPHERE 1:
// Yusov 2013's net density, scattering and ambient sky light tables; 2: Bruneton and Neyret
// 2008's transmittance, irradiance and inscatter tables; 3: Hillaire 2020's transmittance and
// multiple-scattering tables and Firmament's sky irradiance table for it): the light arriving at a
// point of the cloud layer, and the transmittance and in-scattered light of a stretch of ray from
// any point. Read by the particles' shading (clouds/shade_particles.hlsl) and the path-traced
// reference (clouds/trace_clouds.hlsl). The includer declares cbuffers `frame` and `atmosphere`
// (AtmosphereConstants), and SamplerState linearClamp; this file declares the tables (t5..t9) and
// Bruneton's or Hillaire's constants (b4).
#include "atmosphere/atmosphere_structures.hlsli"

#if CLOUD_ATMOSPHERE == 2
#include "atmosphere/bruneton/lookup.hlsli"
cbuffer BrunetonBuffer : register(b4) { BrunetonConstants bruneton; };
Texture2D<float4> transmittanceLut : register(t5);
Texture2D<float4> irradianceLut : register(t6);
Texture3D<float4> inscatterLut : register(t7);
#include "atmosphere/bruneton/camera_segment.hlsli"
#elif CLOUD_ATMOSPHERE == 3
#include "atmosphere/hillaire/camera.hlsli"
cbuffer HillaireBuffer : register(b4) { HillaireConstants hillaire; };
Texture2D<float4> transmittanceLut : register(t5);
Texture2D<float4> multipleScatteringLut : register(t6);
Texture2D<float4> irradianceLut : register(t7);
#else
Texture2D<float4> netDensityLut : register(t5);
Texture3D<float4> singleScatteringLut : register(t6);
Texture3D<float4> highOrderScatteringLut : register(t7);
Texture3D<float4> multipleScatteringLut : register(t8);
Texture2D<float4> ambientLightLut : register(t9);
#include "atmosphere/yusov/view_ray.hlsli"
#endif

// The sun's transmittance from a point `altitude` above the surface to the sun, cosSunZenith from
// the point's vertical, and the sky's irradiance on a horizontal surface there (both per unit
// sun irradiance above the atmosphere).
void lightAt(float altitude, float cosSunZenith, out float3 sunLight, out float3 skyLight) {
#if CLOUD_ATMOSPHERE == 2
    float r = atmosphere.earth.x + altitude;
    sunLight = sunTransmittanceAt(atmosphere, bruneton, transmittanceLut, linearClamp, r, cosSunZenith);
    skyLight = irradianceAt(atmosphere, bruneton, irradianceLut, linearClamp, r, cosSunZenith);
#elif CLOUD_ATMOSPHERE == 3
    float r = atmosphere.earth.x + max(altitude, 0.0);
    sunLight = hillaireTransmittanceToTop(atmosphere, hillaire, transmittanceLut, linearClamp, r, cosSunZenith);
    skyLight = hillaireIrradianceAt(atmosphere, hillaire, irradianceLut, linearClamp, r, cosSunZenith);
#else
    sunLight = sunTransmittance(atmosphere, netDensityLut, linearClamp, altitude, cosSunZenith);
    float width = atmosphere.netDensityLutSize.z;
    skyLight = ambientLightLut.SampleLevel(linearClamp, float2(unitToTexture(saturate(cosSunZenith * 0.5 + 0.5), width), 0.5), 0).rgb;
#endif
}

// lightAt() for a point in the world.
void lightAtPoint(float3 position, out float3 sunLight, out float3 skyLight) {
    float3 fromCentre = position + float3(0.0, atmosphere.earth.x, 0.0);
    float radius = length(fromCentre);
    lightAt(radius - atmosphere.earth.x, dot(fromCentre / radius, frame.directionToSun.xyz), sunLight, skyLight);
}

#if CLOUD_ATMOSPHERE == 1
// The ray from `origin` through Yusov's atmosphere up to `distance` along `direction`.
ViewRay atmosphereRayFrom(float3 origin, float3 direction, float distance, out bool inAtmosphere) {
    float3 earthCentre = float3(0.0, -atmosphere.earth.x, 0.0);
    ViewRay ray;
    ray.camera = origin;
    ray.start = origin - earthCentre;
    ray.viewDir = direction;
    ray.offset = 0.0;
    ray.endsAtBoundary = false;
    inAtmosphere = clipRayToAtmosphere(atmosphere, ray.start, direction, ray.offset);
    ray.hitsGround = inAtmosphere && rayHitsGround(atmosphere, ray.start, direction);
    float toEnd = inAtmosphere ? rayLengthInAtmosphere(atmosphere, ray.start, direction, ray.hitsGround) : 0.0;
    ray.length = clamp(distance - ray.offset, 0.0, toEnd);
    inAtmosphere = inAtmosphere && ray.length > 0.0;
    return ray;
}
#endif

// From `origin` to `distance` along `direction` (to the ground or the atmosphere's top, when
// nearer): the transmittance, and the light scattered in per unit sun irradiance (Yusov's by the
// render modes `modes`: x single, y multiple, z integration steps; Hillaire's by his march, with
// the steps a pixel's view takes beyond the aerial-perspective volume, growing from a start inside
// the atmosphere, as render.hlsl marches).
void atmosphereSegment(float3 origin, float3 direction, float distance, uint4 modes, out float3 transmittance, out float3 inscattered) {
#if CLOUD_ATMOSPHERE == 2
    CameraSegment segment = brunetonSegment(origin, direction, frame.directionToSun.xyz, distance, transmittanceLut, inscatterLut, linearClamp);
    transmittance = segment.transmittance;
    inscattered = segment.light;
#elif CLOUD_ATMOSPHERE == 3
    HillaireCamera from = hillaireCameraAt(atmosphere, origin);
    float offset;
    HillaireView v = hillaireCameraView(atmosphere, from, direction, frame.directionToSun.xyz, offset);
    HillaireSegment segment = hillaireEmptySegment();
    if (offset >= 0.0 && distance > offset)
        segment = hillaireMarch(atmosphere, hillaire, transmittanceLut, multipleScatteringLut, linearClamp, v, 0.0,
                                min(distance - offset, hillaireViewLength(atmosphere, v)), (int)hillaire.aerialPerspective.w, !from.inSpace, segment);
    transmittance = segment.transmittance;
    inscattered = segment.radiance;
#else
    bool inAtmosphere;
    ViewRay ray = atmosphereRayFrom(origin, direction, distance, inAtmosphere);
    transmittance = 1.0;
    inscattered = 0.0;
    if (inAtmosphere) {
        transmittance = transmittanceTo(ray, ray.length);
        inscattered = scatteringAlongRay(ray, frame.directionToSun.xyz, modes.x, modes.y, int(modes.z));
    }
#endif
}

#endif
