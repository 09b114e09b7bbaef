#ifndef FIRMAMENT_BRUNETON_PARAMETERIZATION_HLSLI
#define FIRMAMENT_BRUNETON_PARAMETERIZATION_HLSLI
// Bruneton and Neyret 2008's parameterization of their tables and its inverse.
// The CPU twin, with the mapping explained: src/atmosphere/bruneton/BrunetonParameterization.h.
// Coordinates: r the radius from the Earth's centre; mu, mu_s, nu the cosines of the view
// zenith, sun zenith and sun-view angles. Rg = atmosphere.earth.x, Rt = atmosphere.earth.z.
#include "atmosphere/physics.hlsli"

static const float kTransmittanceMuOffset = 0.15;
static const float kTransmittanceAngle = 1.5;
static const float kIrradianceMuSOffset = 0.2;
static const float kMuSExponent = 3.0;
static const float kMuSOffset = 0.6;
static const float kLowestLayer = 10.0;  // m above the ground: the first layer of the in-scatter table
static const float kHighestLayer = 1.0;  // m below the top: its last

float texelCentre(float u, float n) { return 0.5 / n + u * (1.0 - 1.0 / n); }

// The horizon's zenith cosine seen from radius r: -sqrt(1 - (Rg / r)^2).
float cosHorizonAtRadius(AtmosphereConstants a, float r) {
    float ratio = a.earth.x / r;
    return -sqrt(max(0.0, 1.0 - ratio * ratio));
}

// Transmittance table: u_r = sqrt((r - Rg) / (Rt - Rg)), u_mu = atan((mu + 0.15) / 1.15 tan 1.5) / 1.5.
float2 transmittanceUv(AtmosphereConstants a, BrunetonConstants b, float r, float mu) {
    float ur = sqrt(saturate((r - a.earth.x) / a.earth.y));
    float umu = saturate(atan((mu + kTransmittanceMuOffset) / (1.0 + kTransmittanceMuOffset) * tan(kTransmittanceAngle)) / kTransmittanceAngle);
    return float2(texelCentre(umu, b.transmittanceSize.x), texelCentre(ur, b.transmittanceSize.y));
}
// The r and mu of a texel (u = index / (n - 1)).
void transmittanceTexel(AtmosphereConstants a, BrunetonConstants b, uint2 texel, out float r, out float mu) {
    float2 u = (float2)texel / (b.transmittanceSize.xy - 1.0);
    r = a.earth.x + u.y * u.y * a.earth.y;
    mu = -kTransmittanceMuOffset + tan(kTransmittanceAngle * u.x) / tan(kTransmittanceAngle) * (1.0 + kTransmittanceMuOffset);
}

// Irradiance table: linear in r and mu_s, mu_s from -0.2.
float2 irradianceUv(AtmosphereConstants a, BrunetonConstants b, float r, float muS) {
    float umus = saturate((muS + kIrradianceMuSOffset) / (1.0 + kIrradianceMuSOffset));
    return float2(texelCentre(umus, b.irradianceSize.x), texelCentre(saturate((r - a.earth.x) / a.earth.y), b.irradianceSize.y));
}
void irradianceTexel(AtmosphereConstants a, BrunetonConstants b, uint2 texel, out float r, out float muS) {
    float2 u = (float2)texel / (b.irradianceSize.xy - 1.0);
    r = a.earth.x + u.y * a.earth.y;
    muS = -kIrradianceMuSOffset + u.x * (1.0 + kIrradianceMuSOffset);
}

// Distances along the ray (r, mu) to the ground and to the top of the atmosphere, from
// rho^2 = r^2 - Rg^2 = h (2 Rg + h), which keeps metres near the ground where r^2 - Rg^2 in
// float would lose them; each in the form free of cancellation (the product of the two roots
// of a quadratic is its constant term).
float distanceToGround(float r, float mu, float rho2) {
    float rmu = r * mu;
    return rho2 / max(-rmu + sqrt(max(rmu * rmu - rho2, 0.0)), 1e-3);
}
float distanceToTop(AtmosphereConstants a, float r, float mu, float rho2) {
    float rmu = r * mu;
    float rt = a.earth.z;
    float above = (a.earth.y - (r - a.earth.x)) * (rt + r);  // Rt^2 - r^2
    float root = sqrt(max(rmu * rmu + above, 0.0));
    return rmu > 0.0 ? above / max(rmu + root, 1e-3) : root - rmu;
}
float rho2At(AtmosphereConstants a, float h) { return h * (2.0 * a.earth.x + h); }

// In-scatter table, 4D: (u_r, u_mu, u_mu_s, u_nu) at altitude h, u_mu already a texture
// coordinate in its half (the ground's [0, 0.5), the sky's [0.5, 1]); u_r, u_mu_s and u_nu
// unit coordinates.
float4 inscatterUnit(AtmosphereConstants a, BrunetonConstants b, float h, float mu, float muS, float nu, bool groundHalf) {
    float rg = a.earth.x, rt = a.earth.z;
    float horizonH = sqrt(rt * rt - rg * rg);
    h = max(h, 0.0);
    float rho2 = rho2At(a, h);
    float rho = sqrt(rho2);
    float r = rg + h;
    float n = b.inscatterSize.y;
    float halfWidth = 0.5 - 1.0 / n;
    float4 u;
    u.x = rho / horizonH;
    if (groundHalf) {
        u.y = 0.5 - 0.5 / n - saturate(distanceToGround(r, mu, rho2) / max(rho, 1e-3)) * halfWidth;
    } else {
        u.y = 0.5 + 0.5 / n + saturate(distanceToTop(a, r, mu, rho2) / (rho + horizonH)) * halfWidth;
    }
    u.z = max((1.0 - exp(-kMuSExponent * muS - kMuSOffset)) / (1.0 - exp(-kMuSExponent - kMuSOffset)), 0.0);
    u.w = (1.0 + nu) * 0.5;
    return u;
}

// The world point of a texel of the packed 3D table (x: nu slice * N_mu_s + mu_s, y: mu, z: r).
struct InscatterSample {
    float h, r, rho2;  // altitude, radius, r^2 - Rg^2
    float mu, muS, nu;
    bool groundHalf;
};

InscatterSample inscatterTexel(AtmosphereConstants a, BrunetonConstants b, uint3 texel) {
    float rg = a.earth.x, rt = a.earth.z;
    float horizonH = sqrt(rt * rt - rg * rg);
    float4 n = b.inscatterSize;
    InscatterSample s;
    float3 t = (float3)texel;  // float arithmetic below, never unsigned
    float rho = t.z / (n.x - 1.0) * horizonH;
    s.h = clamp(rho * rho / (sqrt(rho * rho + rg * rg) + rg), kLowestLayer, a.earth.y - kHighestLayer);  // r - Rg = rho^2 / (r + Rg)
    s.r = rg + s.h;
    s.rho2 = rho2At(a, s.h);
    rho = sqrt(s.rho2);
    float halfCount = n.y * 0.5;
    s.groundHalf = texel.y < (uint)halfCount;
    // mu from the law of cosines with the distance d: to the ground Rg^2 = r^2 + 2 r mu d + d^2,
    // to the top Rt^2 = r^2 + 2 r mu d + d^2.
    if (s.groundHalf) {
        float d = clamp((halfCount - 1.0 - t.y) / (halfCount - 1.0) * rho, s.h, rho);
        s.mu = clamp(-(s.rho2 + d * d) / (2.0 * s.r * d), -1.0, 1.0);
    } else {
        float d = clamp((t.y - halfCount) / (halfCount - 1.0) * (rho + horizonH), rt - s.r, rho + horizonH);
        s.mu = clamp((horizonH * horizonH - s.rho2 - d * d) / (2.0 * s.r * d), -1.0, 1.0);
    }
    uint muSTexel = texel.x % (uint)n.z, nuTexel = texel.x / (uint)n.z;
    float umus = (float)muSTexel / (n.z - 1.0);
    s.muS = clamp(-(kMuSOffset + log(1.0 - umus * (1.0 - exp(-kMuSExponent - kMuSOffset)))) / kMuSExponent, -1.0, 1.0);
    float nu = -1.0 + 2.0 * (float)nuTexel / (n.w - 1.0);
    float sines = sqrt(max(0.0, (1.0 - s.mu * s.mu) * (1.0 - s.muS * s.muS)));
    s.nu = clamp(nu, s.mu * s.muS - sines, s.mu * s.muS + sines);
    return s;
}

#endif
