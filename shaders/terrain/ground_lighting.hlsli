#ifndef FIRMAMENT_TERRAIN_GROUND_LIGHTING_HLSLI
#define FIRMAMENT_TERRAIN_GROUND_LIGHTING_HLSLI
// Light reaching a point of the ground, per unit sun irradiance above the atmosphere
// (Yusov 2013, "Terrain shaders"): the sun's light attenuated by the atmosphere's transmittance
// from the point to the top, and the ambient sky light, the irradiance the whole sky gives a
// horizontal surface. Read from the tables of the model that draws the sky:
//   GROUND_LIGHTING=0  no atmosphere: the sun unattenuated above the horizon, and a constant sky
//                      irradiance of kConstantSkyIrradiance (the orientation grid's stand-in);
//   GROUND_LIGHTING=1  Yusov 2013: the net density table and the ambient sky light table;
//   GROUND_LIGHTING=2  Bruneton 2008: the transmittance table and the irradiance table;
//   GROUND_LIGHTING=3  Hillaire 2020: the transmittance table and Firmament's sky irradiance table.
// (A comparison of models draws the ground once per model, each clipped to its columns of the
// frame: src/frame/GroundLighting.h.)
// Callers declare cbuffers `atmosphere` (AtmosphereConstants), for 2 `bruneton` and for 3
// `hillaire`, the tables `sunTransmittanceTable` and `skyIrradianceTable`, and the sampler
// `linearClamp`.
#include "atmosphere/yusov/lookup.hlsli"
#if GROUND_LIGHTING == 2
#include "atmosphere/bruneton/lookup.hlsli"
#elif GROUND_LIGHTING == 3
#include "atmosphere/hillaire/lookup.hlsli"
#endif

static const float kConstantSkyIrradiance = 0.1;

struct GroundLight {
    float3 sunTransmittance;  // T(point -> top of the atmosphere, towards the sun); 0 below the horizon
    float3 skyIrradiance;     // E_sky on a horizontal surface at the point
};

// altitude: metres above the sea-level sphere; cosSunZenith: the sun's direction against the
// local vertical (the direction from the Earth's centre).
GroundLight yusovGroundLight(float altitude, float cosSunZenith, Texture2D<float4> netDensity, Texture2D<float4> ambientLight) {
    GroundLight g;
    g.sunTransmittance = sunTransmittance(atmosphere, netDensity, linearClamp, altitude, cosSunZenith);
    float width = atmosphere.netDensityLutSize.z;
    g.skyIrradiance = ambientLight.SampleLevel(linearClamp, float2(unitToTexture(saturate(cosSunZenith * 0.5 + 0.5), width), 0.5), 0).rgb;
    return g;
}

#if GROUND_LIGHTING == 2
GroundLight brunetonGroundLight(float altitude, float cosSunZenith, Texture2D<float4> transmittance, Texture2D<float4> irradiance) {
    GroundLight g;
    float r = atmosphere.earth.x + altitude;
    g.sunTransmittance = sunTransmittanceAt(atmosphere, bruneton, transmittance, linearClamp, r, cosSunZenith);
    g.skyIrradiance = irradianceAt(atmosphere, bruneton, irradiance, linearClamp, r, cosSunZenith);
    return g;
}
#elif GROUND_LIGHTING == 3
GroundLight hillaireGroundLight(float altitude, float cosSunZenith, Texture2D<float4> transmittance, Texture2D<float4> irradiance) {
    GroundLight g;
    float r = atmosphere.earth.x + max(altitude, 0.0);
    g.sunTransmittance = hillaireTransmittanceToTop(atmosphere, hillaire, transmittance, linearClamp, r, cosSunZenith);
    g.skyIrradiance = hillaireIrradianceAt(atmosphere, hillaire, irradiance, linearClamp, r, cosSunZenith);
    return g;
}
#endif

GroundLight groundLight(float altitude, float cosSunZenith) {
#if GROUND_LIGHTING == 1
    return yusovGroundLight(altitude, cosSunZenith, sunTransmittanceTable, skyIrradianceTable);
#elif GROUND_LIGHTING == 2
    return brunetonGroundLight(altitude, cosSunZenith, sunTransmittanceTable, skyIrradianceTable);
#elif GROUND_LIGHTING == 3
    return hillaireGroundLight(altitude, cosSunZenith, sunTransmittanceTable, skyIrradianceTable);
#else
    GroundLight g;
    g.sunTransmittance = cosSunZenith > 0.0 ? 1.0 : 0.0;
    g.skyIrradiance = kConstantSkyIrradiance * saturate(cosSunZenith * 4.0 + 0.25);
    return g;
#endif
}

// Outgoing radiance of a Lambertian surface, per unit sun irradiance (Yusov 2013's terrain
// shading): albedo / pi * (T_sun * max(N.L, 0) * visibility + E_sky * (1 + N.up) / 2), the last
// factor the ground plane's occlusion of the sky for a surface tilted away from the vertical.
float3 lambertianRadiance(float3 albedo, float3 normal, float3 up, float3 directionToSun, float sunVisibility, GroundLight light) {
    float3 sun = light.sunTransmittance * saturate(dot(normal, directionToSun)) * sunVisibility;
    float3 sky = light.skyIrradiance * saturate((1.0 + dot(up, normal)) * 0.5);
    return albedo / kPi * (sun + sky);
}

#endif
