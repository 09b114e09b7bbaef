#ifndef FIRMAMENT_SINGLE_SCATTERING_HLSLI
#define FIRMAMENT_SINGLE_SCATTERING_HLSLI
// Single scattering along a ray by trapezoidal integration (Yusov 2013, "Computing single
// scattering"; Bruneton and Neyret 2008, eq. 5 without the ground):
//   L1(C, v, l) = integral over [0, D] of T(C -> P) (beta_R rho_R(h) P_R(v.l) + beta_M rho_M(h) P_M(v.l)) T_sun(P) ds
// per unit sun irradiance, where T(C -> P) comes from the densities summed along the way and
// T_sun(P) from the net density table.
#include "atmosphere/yusov/lookup.hlsli"

// Where a ray from `start` (relative to the Earth's centre) along viewDir leaves the
// atmosphere or meets the ground. `hitsGround` says which: a ray below the horizon
// (cos view < c_h) meets the ground, and the ray exactly along the horizon belongs to either
// half of the table, so its texels say. The ground distance -b - sqrt(max(b^2 - c, 0)) stays
// defined at the tangent and is 0 for a ray that starts on the ground.
float rayLengthInAtmosphere(AtmosphereConstants a, float3 start, float3 viewDir, bool hitsGround) {
    if (hitsGround) {
        float b = dot(start, viewDir);
        float c = dot(start, start) - a.earth.x * a.earth.x;
        return max(-b - sqrt(max(b * b - c, 0.0)), 0.0);
    }
    return max(raySphere(start, viewDir, a.earth.z).y, 0.0);
}

bool rayHitsGround(AtmosphereConstants a, float3 start, float3 viewDir) {
    float radius = length(start);
    return dot(start / radius, viewDir) < cosHorizon(a, radius - a.earth.x);
}

float3 integrateSingleScattering(AtmosphereConstants a, Texture2D<float4> netDensityLut, SamplerState linearClamp, float3 start,
                                 float3 viewDir, float3 sunDir, float rayLength, int steps) {
    float stepLength = rayLength / steps;
    float cosTheta = dot(viewDir, sunDir);
    float3 density = particleDensity(a, length(start) - a.earth.x);
    float3 integrand = scatteringCoefficient(a, density, cosTheta) *
                       sunTransmittance(a, netDensityLut, linearClamp, length(start) - a.earth.x, dot(normalize(start), sunDir));
    float3 netDensityFromStart = 0.0;
    float3 inscattering = 0.0;
    for (int i = 1; i <= steps; ++i) {
        float3 position = start + viewDir * (i * stepLength);
        float radius = length(position);
        float h = radius - a.earth.x;
        float3 nextDensity = particleDensity(a, h);
        netDensityFromStart += (density + nextDensity) * (0.5 * stepLength);
        float3 nextIntegrand = scatteringCoefficient(a, nextDensity, cosTheta) * exp(-opticalDepth(a, netDensityFromStart)) *
                               sunTransmittance(a, netDensityLut, linearClamp, h, dot(position / radius, sunDir));
        inscattering += (integrand + nextIntegrand) * (0.5 * stepLength);
        density = nextDensity;
        integrand = nextIntegrand;
    }
    return inscattering;
}

#endif
