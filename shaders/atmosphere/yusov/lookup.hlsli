#ifndef FIRMAMENT_LUT_LOOKUP_HLSLI
#define FIRMAMENT_LUT_LOOKUP_HLSLI
// Look-ups into the pre-computed tables: the net density to the atmosphere's top (2D) and
// the 4D scattering tables packed into 3D textures (Yusov 2013, "Performing look-ups into
// the table"). The single and all-orders tables hold two banks of altitude texels side by side,
// one per species (lookUpSpeciesScattering).
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

// The 4D tables hold their light times kTableScale (the pre-computation writes it so, every
// look-up divides it out; YusovPrecomputation.h's kYusovTableScale is the same number). They are
// half floats, whose normal range ends at 6e-5 and whose subnormals step by 6e-8: unscaled, the
// light of a sun 8 degrees down (about 1e-6 of its irradiance at the zenith) kept 6% steps, and at
// 11 degrees down (4e-8) less than one step, so the sky of deep twilight was rounding noise. Times
// 1e4, 1e-6 is a normal number and 1e-10 keeps a few bits; the largest light, under 2 (the
// Rayleigh bank of the all-orders table: S_R + L^H / P_R), stays far below half's 65504.
static const float kTableScale = 1e4;

// Light scattered by each species, without its phase function: S_R and S_M.
struct SpeciesScattering {
    float3 rayleigh;
    float3 mie;
};

// L = P_R(v.l) S_R + P_M(v.l) S_M.
float3 withPhases(AtmosphereConstants a, SpeciesScattering s, float cosTheta) {
    return s.rayleigh * rayleighPhase(cosTheta) + s.mie * miePhase(cosTheta, a.mieScattering.w);
}

// Where a look-up reads the packed 4D table for the point `position` (relative to the Earth's
// centre) looking along viewDir with the sun along sunDir: the texture coordinates in the two
// sun-view slices around it, and the weight of the second. u spans one bank of altitude texels.
struct TableSample {
    float3 uvw0, uvw1;
    float weight;
    float stepsBelow;  // how far the sun is below the table's lowest sun, in sun-zenith texels there (0 above)
    float nextSun;     // z from a sun-zenith texel to the next one up
};

TableSample tableSample(AtmosphereConstants a, float3 position, float3 viewDir, float3 sunDir, inout int horizonSide) {
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
    TableSample t;
    t.uvw0.x = unitToTexture(altitudeToUnit(a, h), n.x);
    t.uvw0.y = viewZenithToTexture(viewZenithToUnit(cosView, cosHorizonAngle, above), n.y, above);
    float sunZenith = unitToTexture(sunZenithToUnit(cosSun), n.z);
    float slice = sunViewToUnit(cosSunView) * (n.w - 1.0);
    float slice0 = clamp(floor(slice), 0.0, n.w - 2.0);
    t.weight = saturate(slice - slice0);
    t.uvw0.z = (slice0 + sunZenith) / n.w;
    t.uvw1 = float3(t.uvw0.xy, t.uvw0.z + 1.0 / n.w);
    float texelSpacing = unitToSunZenith(1.0 / (n.z - 1.0)) - kSunZenithMinCos;
    t.stepsBelow = max(kSunZenithMinCos - cosSun, 0.0) / texelSpacing;
    t.nextSun = 1.0 / (n.z * n.w);
    return t;
}

// Trilinear in the 3D texture, linear between the two sun-view slices, the sun `sunShift` in z
// from the sample's; `bank` of `banks` side by side along u.
float3 sampleTableAt(Texture3D<float4> lut, SamplerState linearClamp, TableSample t, float sunShift, float bank, float banks) {
    float3 shift = float3(bank, 0.0, sunShift);
    float3 scale = float3(1.0 / banks, 1.0, 1.0);
    return lerp(lut.SampleLevel(linearClamp, (t.uvw0 + shift) * scale, 0).rgb, lut.SampleLevel(linearClamp, (t.uvw1 + shift) * scale, 0).rgb,
                t.weight) /
           kTableScale;
}

// The table's light at the sample. Eq. 6 ends the sun's axis at 11.4 degrees below the horizon;
// a lower sun would read the light of that one, a glow that never fades (docs/atmosphere.md,
// "Twilight"). Below it the light goes on falling as it falls over the axis's last texel, by the
// same factor per texel's width of the sun's cosine: L = L_0 (L_0 / L_1)^steps, per channel, never
// rising.
float3 sampleTable(Texture3D<float4> lut, SamplerState linearClamp, TableSample t, float bank, float banks) {
    float3 light = sampleTableAt(lut, linearClamp, t, 0.0, bank, banks);
    if (t.stepsBelow > 0.0) {
        float3 above = sampleTableAt(lut, linearClamp, t, t.nextSun, bank, banks);
        light *= pow(saturate(light / max(above, 1e-30)), t.stepsBelow);
    }
    return light;
}

// The in-scattered radiance, per unit sun irradiance, of a table that stores it as it is: the
// higher orders of scattering, which the integrals over the sphere leave smooth in the sun-view
// angle.
float3 lookUpScattering(AtmosphereConstants a, Texture3D<float4> lut, SamplerState linearClamp, float3 position, float3 viewDir,
                        float3 sunDir, inout int horizonSide) {
    return sampleTable(lut, linearClamp, tableSample(a, position, viewDir, sunDir, horizonSide), 0.0, 1.0);
}

// The same from a table of species, which stores S_R in its first bank of altitude texels and
// S_M in its second, and the radiance with the phases applied here. The phases carry the aerosols'
// forward peak, which no interpolation between sun-view slices resolves: the table with the phases
// applied read up to twice the light near the zenith under a high sun (docs/atmosphere.md, "A
// table of species"). The all-orders table stores the higher orders in its Rayleigh bank, divided
// by P_R at its texels (Bruneton and Neyret 2008 do the same).
float3 lookUpSpeciesScattering(AtmosphereConstants a, Texture3D<float4> lut, SamplerState linearClamp, float3 position, float3 viewDir,
                               float3 sunDir, inout int horizonSide) {
    TableSample t = tableSample(a, position, viewDir, sunDir, horizonSide);
    SpeciesScattering s;
    s.rayleigh = sampleTable(lut, linearClamp, t, 0.0, 2.0);
    s.mie = sampleTable(lut, linearClamp, t, 1.0, 2.0);
    return withPhases(a, s, dot(viewDir, sunDir));
}

#endif
