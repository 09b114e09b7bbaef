#ifndef FIRMAMENT_LUT_LOOKUP_HLSLI
#define FIRMAMENT_LUT_LOOKUP_HLSLI
// Look-ups into the pre-computed tables: the net density to the atmosphere's top (2D) and
// the 4D scattering tables packed into 3D textures (Yusov 2013, "Performing look-ups into
// the table").
#include "atmosphere/yusov/parameterization.hlsli"

// Net density table: u is the cosine of the zenith angle, linear over [-1, 1]; v is the
// altitude, with eq. 4's square root so that texels crowd near the ground where the densities
// change fastest. Rays that hit the Earth store the grazing ray's value; sunTransmittance()
// makes them dark with an exact horizon test instead, so filtering never blurs the horizon.
float3 netDensityToTop(AtmosphereConstants a, Texture2D<float4> lut, SamplerState linearClamp, float h, float cosZenith) {
    float2 n = a.netDensityLutSize.xy;  // x: altitudes (rows), y: zenith cosines (columns)
    float2 uv = float2(unitToTexture(saturate(cosZenith * 0.5 + 0.5), n.y), unitToTexture(altitudeToUnit(a, h), n.x));
    return lut.SampleLevel(linearClamp, uv, 0).xyz;
}

// Transmittance from altitude h to the top of the atmosphere towards the sun (cosine of its
// zenith angle given); zero below the horizon, where the Earth hides the sun.
float3 sunTransmittance(AtmosphereConstants a, Texture2D<float4> lut, SamplerState linearClamp, float h, float cosSunZenith) {
    if (cosSunZenith < cosHorizon(a, h)) return 0.0;
    return exp(-opticalDepth(a, netDensityToTop(a, lut, linearClamp, h, cosSunZenith)));
}

// Which half of the view-zenith axis a ray's look-ups use. Every look-up along one ray must
// use the same half, or the horizon shows as a seam: the first decides, the rest follow.
static const int kHorizonUndecided = -1;
static const int kBelowHorizon = 0;
static const int kAboveHorizon = 1;

// The in-scattered radiance, per unit sun irradiance, stored in a 4D table for the point
// `position` (relative to the Earth's centre) looking along viewDir with the sun along sunDir.
// Trilinear in the 3D texture, linear between the two sun-view slices.
float3 lookUpScattering(AtmosphereConstants a, Texture3D<float4> lut, SamplerState linearClamp, float3 position, float3 viewDir,
                        float3 sunDir, inout int horizonSide) {
    float radius = length(position);
    float3 up = position / radius;
    float h = clamp(radius - a.earth.x, 0.0, a.earth.y);
    float cosView = dot(up, viewDir);
    float cosSun = dot(up, sunDir);
    float cosSunView = dot(viewDir, sunDir);
    float cosHorizonAngle = cosHorizon(a, h);
    if (horizonSide == kHorizonUndecided) horizonSide = cosView > cosHorizonAngle ? kAboveHorizon : kBelowHorizon;
    bool above = horizonSide == kAboveHorizon;

    float4 n = a.scatteringLutSize;
    float3 uvw0;
    uvw0.x = unitToTexture(altitudeToUnit(a, h), n.x);
    uvw0.y = viewZenithToTexture(viewZenithToUnit(cosView, cosHorizonAngle, above), n.y, above);
    float sunZenith = unitToTexture(sunZenithToUnit(cosSun), n.z);
    float slice = sunViewToUnit(cosSunView) * (n.w - 1.0);
    float slice0 = clamp(floor(slice), 0.0, n.w - 2.0);
    float weight = saturate(slice - slice0);
    uvw0.z = (slice0 + sunZenith) / n.w;
    float3 uvw1 = float3(uvw0.xy, uvw0.z + 1.0 / n.w);
    return lerp(lut.SampleLevel(linearClamp, uvw0, 0).rgb, lut.SampleLevel(linearClamp, uvw1, 0).rgb, weight);
}

#endif
