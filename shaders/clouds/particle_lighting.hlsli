#ifndef FIRMAMENT_PARTICLE_LIGHTING_HLSLI
#define FIRMAMENT_PARTICLE_LIGHTING_HLSLI
// The light a cloud particle scatters, from the reference sphere's scattering table
// (src/clouds/ParticleScattering.h; docs/clouds.md, "Scattering table"). The includer declares
// Texture3D<float2> scatteringTable, SamplerState linearWrap and cbuffer `shading`
// (CloudShadingConstants); kTablePi comes from clouds/optical_depth_table.hlsli.

static const float kDropletAsymmetry = 0.9;  // Henyey-Greenstein g of the droplets (the table's)
// The share of the extinction that multiply scattered light sees: the delta-M scaled medium
// (Wiscombe 1977) of the table's orders 2 and on, 1 - g^2 (src/clouds/LightSpace.h).
static const float kScaledExtinctionShare = 1.0 - kDropletAsymmetry * kDropletAsymmetry;

// Henyey and Greenstein 1941: the phase function (1/sr) for the cosine of the scattering angle.
float henyeyGreenstein(float cosine, float g) {
    float denominator = 1.0 + g * g - 2.0 * g * cosine;
    return (1.0 - g * g) / (4.0 * kTablePi * denominator * sqrt(denominator));
}

// The scattering table at a ray entering the unit sphere at s along d, the sun along l (all in
// the particle's unit-sphere space): x single scattering without the phase, y multiple.
float2 particleScattering(float3 s, float3 d, float3 l) {
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
    return scatteringTable.SampleLevel(linearWrap, u, 0.0);
}

#endif
