#ifndef FIRMAMENT_PARTICLE_LIGHTING_HLSLI
#define FIRMAMENT_PARTICLE_LIGHTING_HLSLI
// The light a cloud particle scatters: the scattering table's spheres of every optical radius
// (src/clouds/ParticleScattering.h; docs/clouds.md, "Scattering table"), and deck diffusion
// (docs/clouds.md, "Deck diffusion"). The includer declares
// Texture3D<float4> scatteringTable, Texture3D<float> deckDiffusionTable, SamplerState linearWrap
// and linearClamp and cbuffer `shading` (CloudShadingConstants); kTablePi comes from
// clouds/optical_depth_table.hlsli.

static const float kDropletAsymmetry = 0.9;  // Henyey-Greenstein g of the droplets (the table's)
// The share of the extinction that light scattered into the droplets' forward peak still sees:
// the delta-M scaled medium (Wiscombe 1977), 1 - g^2 (src/clouds/LightSpace.h).
static const float kScaledExtinctionShare = 1.0 - kDropletAsymmetry * kDropletAsymmetry;

// Henyey and Greenstein 1941: the phase function (1/sr) for the cosine of the scattering angle.
float henyeyGreenstein(float cosine, float g) {
    float denominator = 1.0 + g * g - 2.0 * g * cosine;
    return (1.0 - g * g) / (4.0 * kTablePi * denominator * sqrt(denominator));
}

// The scattering table at a ray entering the unit sphere at s along d, the sun along l (all in
// the particle's unit-sphere space), for a sphere of optical radius `opticalRadius`: x single
// scattering and z the forward peak's, both without the phase, y multiple; linear in log2 of the optical radius between the
// table's layers (each doubles the one before), clamped to the thinnest and the thickest.
float3 particleScattering(float3 s, float3 d, float3 l, float opticalRadius) {
    float entryAngle = acos(clamp(dot(s, l), -1.0, 1.0));
    float3 z = -s;
    float3 across = l - dot(l, z) * z;
    float len = length(across);
    float3 x = len > 1e-5 ? across / len : float3(1.0, 0.0, 0.0);
    if (len <= 1e-5 && abs(z.x) > 0.9) x = float3(0.0, 1.0, 0.0);
    x = normalize(x - dot(x, z) * z);
    float3 y = cross(z, x);
    float azimuth = atan2(dot(d, y), dot(d, x));
    float zenith = acos(clamp(dot(d, z), 0.0, 1.0));
    float3 n = shading.scattering.xyz;
    float3 u = float3(entryAngle / kTablePi, azimuth / (2.0 * kTablePi) + 0.5, zenith / (0.5 * kTablePi));
    u.x = clamp(u.x, 0.5 / n.x, 1.0 - 0.5 / n.x);
    u.z = clamp(u.z, 0.5 / n.z, 1.0 - 0.5 / n.z);
    // The layers: blocks of n.z slices along the texture's depth, filtered by hand between two.
    float layers = shading.scattering.w;
    float layer = clamp(log2(max(opticalRadius, 1e-6) / shading.light.x), 0.0, layers - 1.0);
    float layer0 = min(floor(layer), max(layers - 2.0, 0.0));
    float weight = layer - layer0;
    float3 a = scatteringTable.SampleLevel(linearWrap, float3(u.xy, (layer0 + u.z) / layers), 0.0).xyz;
    float3 b = scatteringTable.SampleLevel(linearWrap, float3(u.xy, (min(layer0 + 1.0, layers - 1.0) + u.z) / layers), 0.0).xyz;
    return a + weight * (b - a);
}

// Deck diffusion (src/reference/DeckDiffusion.h, whose deckDiffuseRadiance() is the CPU twin): the
// delta-Eddington (Joseph, Wiscombe and Weinman 1976) diffuse radiance (1/sr, per unit sun
// irradiance) at optical depth `depth` of a conservatively scattering slab of optical thickness
// `total` lit along its normal, both along the sun's rays and unscaled, travelling at cosine mu
// to the sun's light (1: away from the sun). In the delta-M scaled medium (t = (1 - g^2) depth,
// g' = g / (1 + g)), Eddington's radiance I = I0 + mu I1 with k = 3 / (4 pi):
//   I1 = C1 - k e^(-t),  I0 = C0 - (1 - g') C1 t - k e^(-t),
//   C1 = k (5 - e^(-T)) / (4 + 3 (1 - g') T),  C0 = 5 k / 3 - 2 C1 / 3 (Marshak's conditions).
float deckDiffuseRadiance(float depth, float total, float mu) {
    float f = kDropletAsymmetry * kDropletAsymmetry;
    float g = (kDropletAsymmetry - f) / (1.0 - f);
    float t = (1.0 - f) * depth, T = (1.0 - f) * total;
    float k = 3.0 / (4.0 * kTablePi);
    float c1 = k * (5.0 - exp(-T)) / (4.0 + 3.0 * (1.0 - g) * T);
    float c0 = 5.0 / 3.0 * k - 2.0 / 3.0 * c1;
    float i1 = c1 - k * exp(-t);
    float i0 = c0 - (1.0 - g) * c1 * t - k * exp(-t);
    return max(i0 + mu * i1, 0.0);
}

// The part of deckDiffuseRadiance() scattered once, under the same approximations (the scaled
// medium, Eddington's phase function 1 + 3 g' mu): the direct beam e^(-t') scattered at every
// depth t' and carried to t, downward (mu > 0) from the top, upward (m = -mu) from the bottom:
//   (1 + 3 g' mu) / (4 pi) (e^(-t) - e^(-t / mu)) / (1 - mu),  mu > 0 (t e^(-t) at mu = 1)
//   (1 + 3 g' mu) / (4 pi) (e^(-t) - e^(-T - (T - t) / m)) / (1 + m),  mu < 0
// The renderer's single scattering is the table's (exact, in the particle), so deck diffusion
// adds only the rest: deckDiffuseRadiance() - this (Nakajima and Tanaka 1988).
float deckSingleScattering(float depth, float total, float mu) {
    float f = kDropletAsymmetry * kDropletAsymmetry;
    float g = (kDropletAsymmetry - f) / (1.0 - f);
    float t = (1.0 - f) * depth, T = (1.0 - f) * total;
    float phase = max(1.0 + 3.0 * g * mu, 0.0) / (4.0 * kTablePi);
    float m = abs(mu);
    float carried;
    if (mu > 0.0)
        carried = abs(1.0 - mu) < 1e-3 ? t * exp(-t) : (exp(-t) - exp(-t / mu)) / (1.0 - mu);
    else
        carried = m < 1e-4 ? 0.0 : (exp(-t) - exp(-T - (T - t) / m)) / (1.0 + m);
    return phase * carried;
}

// Deck diffusion's light scattered more than once.
float deckMultipleScattering(float depth, float total, float mu) {
    return max(deckDiffuseRadiance(depth, total, mu) - deckSingleScattering(depth, total, mu), 0.0);
}

// Deck diffusion, solved slab (the default; docs/clouds.md, "Deck diffusion"; src/clouds/
// DeckDiffusionTable.h): the radiance scattered more than once (1/sr, per unit sun irradiance) at
// optical depth `depth` of a slab of cloud of optical thickness `total` lit along its normal, both
// along the sun's rays, travelling at cosine mu to the sun's light (1: away from the sun), from
// the table solved by doubling and adding in the droplets' own medium (g = 0.9; no delta-Eddington
// scaling). Node k of each axis at texel k: the cosine -cos(pi k / (cosines - 1)) (even steps in
// angle), the depth's share (1 - cos(pi k / (depths - 1))) / 2, the thickness thinnest x
// 2^(k / per octave); a slab thinner than the thinnest scales as light scattered twice, by the
// thickness squared. src/reference/DeckDiffusion.h's solvedSlabMultipleScattering() is the CPU twin.
float solvedSlabMultipleScattering(float depth, float total, float mu) {
    float4 n = shading.deck;
    float thinnest = shading.light.z;
    float x = acos(-clamp(mu, -1.0, 1.0)) / kTablePi * (n.x - 1.0);
    float share = total > 0.0 ? saturate(depth / total) : 0.0;
    float y = acos(1.0 - 2.0 * share) / kTablePi * (n.y - 1.0);
    float z = clamp(log2(max(total, 1e-30) / thinnest) * n.w, 0.0, n.z - 1.0);
    float thin = total / thinnest;
    float scale = total < thinnest ? thin * thin : 1.0;
    return scale * deckDiffusionTable.SampleLevel(linearClamp, (float3(x, y, z) + 0.5) / n.xyz, 0.0);
}

#endif
