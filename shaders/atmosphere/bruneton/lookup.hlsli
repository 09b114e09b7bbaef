#ifndef FIRMAMENT_BRUNETON_LOOKUP_HLSLI
#define FIRMAMENT_BRUNETON_LOOKUP_HLSLI
// Look-ups into Bruneton and Neyret 2008's tables: transmittance to the top of
// the atmosphere, ground irradiance, and the 4D in-scatter table packed into 3D.
#include "atmosphere/bruneton/parameterization.hlsli"

// Transmittance from radius r to the top along zenith cosine mu. The table holds, for rays
// that meet the ground, the grazing ray's value: callers test the horizon themselves.
float3 transmittanceToTop(AtmosphereConstants a, BrunetonConstants b, Texture2D<float4> lut, SamplerState linearClamp, float r, float mu) {
    return lut.SampleLevel(linearClamp, transmittanceUv(a, b, r, mu), 0).rgb;
}

// The sun's light reaching radius r at sun zenith cosine mu_s: zero where the Earth hides it.
float3 sunTransmittanceAt(AtmosphereConstants a, BrunetonConstants b, Texture2D<float4> lut, SamplerState linearClamp, float r, float muS) {
    return muS < cosHorizonAtRadius(a, r) ? 0.0 : transmittanceToTop(a, b, lut, linearClamp, r, muS);
}

// Transmittance between the point at radius r and the point at distance d along zenith cosine
// mu, as a ratio of two transmittances to the top (Bruneton 2008, eq. in section 4): along the
// ray where it rises, against it where it falls.
float3 transmittanceAlong(AtmosphereConstants a, BrunetonConstants b, Texture2D<float4> lut, SamplerState linearClamp, float r, float mu,
                          float d) {
    float r1 = sqrt(max(r * r + d * d + 2.0 * r * mu * d, a.earth.x * a.earth.x));
    float mu1 = clamp((r * mu + d) / r1, -1.0, 1.0);
    float3 ratio = mu > 0.0 ? transmittanceToTop(a, b, lut, linearClamp, r, mu) / max(transmittanceToTop(a, b, lut, linearClamp, r1, mu1), 1e-30)
                            : transmittanceToTop(a, b, lut, linearClamp, r1, -mu1) / max(transmittanceToTop(a, b, lut, linearClamp, r, -mu), 1e-30);
    return min(ratio, 1.0);
}

// Both tables end the sun's axis at mu_s = -0.2, 11.5 degrees below the horizon; a lower sun
// would read the light of that one, a glow that never fades (docs/atmosphere.md, "Twilight").
// Below it the light goes on falling as it falls over the axis's last texel, by the same factor
// per texel's width of mu_s: L = L_0 (L_0 / L_1)^steps, per channel, never rising.
static const float kLowestSun = -kIrradianceMuSOffset;
float4 fadeBelowTable(float4 atEnd, float4 nextUp, float steps) {
    return steps > 0.0 ? atEnd * pow(saturate(atEnd / max(nextUp, 1e-30)), steps) : atEnd;
}

// Irradiance on a horizontal surface at radius r, per unit sun irradiance.
float3 irradianceAt(AtmosphereConstants a, BrunetonConstants b, Texture2D<float4> lut, SamplerState linearClamp, float r, float muS) {
    float3 light = lut.SampleLevel(linearClamp, irradianceUv(a, b, r, muS), 0).rgb;
    if (muS >= kLowestSun) return light;
    float spacing = (1.0 - kLowestSun) / (b.irradianceSize.x - 1.0);
    float3 nextUp = lut.SampleLevel(linearClamp, irradianceUv(a, b, r, kLowestSun + spacing), 0).rgb;
    return fadeBelowTable(float4(light, 0.0), float4(nextUp, 0.0), (kLowestSun - muS) / spacing).rgb;
}

// A 4D table at unit coordinates u (u_r, u_mu as a texture coordinate, u_mu_s, u_nu):
// trilinear in the 3D texture, linear between the two nu slices by hand.
float4 sampleInscatterAt(BrunetonConstants b, Texture3D<float4> lut, SamplerState linearClamp, float4 u) {
    float4 n = b.inscatterSize;
    float slice = u.w * (n.w - 1.0);
    float slice0 = clamp(floor(slice), 0.0, n.w - 2.0);
    float weight = saturate(slice - slice0);
    float x = (slice0 + texelCentre(u.z, n.z)) / n.w;
    float3 uvw = float3(x, u.y, texelCentre(u.x, n.x));
    return lerp(lut.SampleLevel(linearClamp, uvw, 0), lut.SampleLevel(linearClamp, uvw + float3(1.0 / n.w, 0.0, 0.0), 0), weight);
}

// A 4D table at (altitude h, mu, mu_s, nu), in the half of the view zenith axis `groundHalf` says,
// as it is stored (the delta tables, or S before its scale is divided out); faded below the lowest sun.
float4 sampleInscatter(AtmosphereConstants a, BrunetonConstants b, Texture3D<float4> lut, SamplerState linearClamp, float h, float mu,
                       float muS, float nu, bool groundHalf) {
    float4 u = inscatterUnit(a, b, h, mu, muS, nu, groundHalf);
    float4 light = sampleInscatterAt(b, lut, linearClamp, u);
    if (muS >= kLowestSun) return light;
    // mu_s of the axis's second texel, from u_mu_s = (1 - e^(-3 mu_s - 0.6)) / (1 - e^(-3.6)).
    float second = 1.0 / (b.inscatterSize.z - 1.0);
    float spacing = (-log(1.0 - second * (1.0 - exp(-kMuSExponent - kMuSOffset))) - kMuSOffset) / kMuSExponent - kLowestSun;
    float4 nextUp = sampleInscatterAt(b, lut, linearClamp, float4(u.x, u.y, second, u.w));
    return fadeBelowTable(light, nextUp, (kLowestSun - muS) / spacing);
}

// The in-scatter table S holds its light times kInscatterScale: the pre-computation writes it
// so (precompute_inscatter.hlsl's initial and accumulate), lookUpInscatter divides it out, and
// BrunetonPrecomputation.h's kBrunetonInscatterScale is the same number. The table is half floats,
// whose normal range ends at 6.1e-5 and whose subnormals step by 6e-8: unscaled, twilight's sky
// (S about 2e-5 per unit sun irradiance at the zenith with the sun 8 degrees down, 1e-6 at 12)
// kept a few bits or none. Times 1e3 it is normal. Yusov's tables use 1e4; this one stops at 1e3
// because its largest light is larger: 6.5 per unit irradiance with the settings' haziest air
// (aerosol density 5, no absorption), a white ground and 10 orders (the higher orders over P_R
// near nu = 0), which 1e4 would put within 1% of half's largest number, 65504.
// The delta tables are float32 and unscaled: sampleInscatter reads those as they are.
static const float kInscatterScale = 1e3;

// S from the in-scatter table itself (sampleInscatter, the scale divided out).
float4 lookUpInscatter(AtmosphereConstants a, BrunetonConstants b, Texture3D<float4> lut, SamplerState linearClamp, float h, float mu,
                       float muS, float nu, bool groundHalf) {
    return sampleInscatter(a, b, lut, linearClamp, h, mu, muS, nu, groundHalf) / kInscatterScale;
}

// Single Mie scattering's colour from its red channel (Bruneton and Neyret 2008, "getMie"): the table keeps
// Rayleigh's RGB and Mie's red only; Mie's other channels follow from the ratio of the two
// species, which single scattering makes close to beta_M / beta_R per channel.
float3 mieFromRed(AtmosphereConstants a, float4 rayleighMie) {
    return rayleighMie.rgb * rayleighMie.w / max(rayleighMie.r, 1e-12) * (a.rayleighScattering.r / a.rayleighScattering.rgb) *
           (a.mieScattering.rgb / a.mieScattering.r);
}

#endif
