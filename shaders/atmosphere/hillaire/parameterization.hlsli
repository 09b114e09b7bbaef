#ifndef FIRMAMENT_HILLAIRE_PARAMETERIZATION_HLSLI
#define FIRMAMENT_HILLAIRE_PARAMETERIZATION_HLSLI
// Hillaire 2020's parameterization of its tables on the GPU: the twin of
// src/atmosphere/hillaire/HillaireParameterization (whose header explains each mapping), held to
// it by the test HillaireTables.ParameterizationMatchesTheCpu. Radii from the Earth's centre (m),
// unit coordinates in [0, 1].
#include "atmosphere/atmosphere_structures.hlsli"

static const float kHillairePi = 3.14159265358979;

// rho^2 = r^2 - Rg^2, as (r - Rg)(r + Rg): single precision keeps the altitude's digits that way.
float hillaireHorizonDistanceSquared(AtmosphereConstants a, float r) { return max((r - a.earth.x) * (r + a.earth.x), 0.0); }

// The far root of |x + d v| = Rt from radius r along the zenith cosine mu.
float hillaireDistanceToTop(AtmosphereConstants a, float r, float mu) {
    float discriminant = max(r * r * (mu * mu - 1.0) + a.earth.z * a.earth.z, 0.0);
    return max(-r * mu + sqrt(discriminant), 0.0);
}

// Transmittance table: (x_mu, x_r), Bruneton 2017's mapping.
float2 hillaireTransmittanceUnit(AtmosphereConstants a, float r, float mu) {
    float H = sqrt(hillaireHorizonDistanceSquared(a, a.earth.z));
    float rho = sqrt(hillaireHorizonDistanceSquared(a, r));
    float dMin = a.earth.z - r, dMax = rho + H;
    float d = hillaireDistanceToTop(a, r, mu);
    float xMu = dMax > dMin ? (d - dMin) / (dMax - dMin) : 0.0;
    return float2(saturate(xMu), saturate(rho / H));
}

// ... and back: (r, mu).
float2 hillaireTransmittanceCoordinates(AtmosphereConstants a, float2 unit) {
    float H = sqrt(hillaireHorizonDistanceSquared(a, a.earth.z));
    float rho = H * unit.y;
    float r = sqrt(rho * rho + a.earth.x * a.earth.x);
    float dMin = a.earth.z - r, dMax = rho + H;
    float d = dMin + unit.x * (dMax - dMin);
    float mu = d == 0.0 ? 1.0 : clamp((H * H - rho * rho - d * d) / (2.0 * r * d), -1.0, 1.0);
    return float2(r, mu);
}

// Multiple scattering table: (0.5 + 0.5 mu_s, (r - Rg) / (Rt - Rg)), and back: (r, mu_s).
float2 hillaireMultipleScatteringUnit(AtmosphereConstants a, float r, float muS) {
    return saturate(float2(0.5 + 0.5 * muS, (r - a.earth.x) / a.earth.y));
}
float2 hillaireMultipleScatteringCoordinates(AtmosphereConstants a, float2 unit) { return float2(a.earth.x + unit.y * a.earth.y, 2.0 * unit.x - 1.0); }

// The zenith angle of the true horizon from radius r.
float hillaireHorizonZenithAngle(AtmosphereConstants a, float r) {
    return kHillairePi - acos(saturate(sqrt(hillaireHorizonDistanceSquared(a, r)) / r));
}

// Sky-view table at radius r: (u, v) for a view of zenith cosine mu whose azimuth from the sun's
// has the cosine cosAzimuth.
float2 hillaireSkyViewUnit(AtmosphereConstants a, float r, float mu, float cosAzimuth) {
    float horizon = hillaireHorizonZenithAngle(a, r), beta = kHillairePi - horizon;
    float theta = acos(clamp(mu, -1.0, 1.0));
    float v = theta < horizon ? 0.5 * (1.0 - sqrt(max(1.0 - theta / horizon, 0.0)))
                              : 0.5 * (1.0 + sqrt(saturate((theta - horizon) / beta)));
    return float2(sqrt(saturate(0.5 - 0.5 * cosAzimuth)), v);
}

// ... and back: (mu, cosAzimuth).
float2 hillaireSkyViewDirection(AtmosphereConstants a, float r, float2 unit) {
    float horizon = hillaireHorizonZenithAngle(a, r), beta = kHillairePi - horizon;
    float s = abs(2.0 * unit.y - 1.0);
    float theta = unit.y < 0.5 ? horizon * (1.0 - s * s) : horizon + beta * s * s;
    return float2(cos(theta), 1.0 - 2.0 * unit.x * unit.x);
}

#endif
