#ifndef FIRMAMENT_HILLAIRE_MARCH_HLSLI
#define FIRMAMENT_HILLAIRE_MARCH_HLSLI
// Hillaire 2020's ray march (section 5.4 and 5.5), shared by the sky-view table, the aerial
// perspective volume, the per-pixel march and the sky irradiance table. Along a view from x,
// per unit sun irradiance,
//   L = integral over [t0, t1] of T(x, y) S(y) dt,
//   S(y) = (sigma_R(y) P_R(nu) + sigma_M(y) P_M(nu)) T_sun(y) + (sigma_R(y) + sigma_M(y)) Psi_ms(y),
// the first term single scattering (T_sun from the transmittance table, zero where the Earth
// hides the sun), the second every higher order by the multiple-scattering table. Each step
// holds S and the extinction sigma_t at its middle and integrates T across the step exactly
// (Hillaire 2015's energy-conserving step): T(x, y) S (1 - exp(-sigma_t dt)) / sigma_t. The steps
// are equal, or (a whole view: the sky view, a pixel's march) grow as the square of their index,
// t_i = t0 + (t1 - t0) (i / N)^2 as the paper's sample spaces them, so that the first few
// kilometres, where the aerosols are, are not crossed in one step.
// The CPU twin: src/reference/HillaireMultipleScatteringTwin (hillaireRadiance).
#include "atmosphere/hillaire/lookup.hlsli"
#include "atmosphere/physics.hlsli"

// A view from radius r (rho2 = r^2 - Rg^2, kept apart for precision near the ground) along the
// zenith cosine mu, the sun at zenith cosine muS, nu the cosine between the view and the sun.
struct HillaireView {
    float r, rho2, mu, muS, nu;
};

// What a march has gathered so far: in-scattered radiance per unit sun irradiance and the
// transmittance from the view's start.
struct HillaireSegment {
    float3 radiance;
    float3 transmittance;
};

HillaireSegment hillaireEmptySegment() {
    HillaireSegment s;
    s.radiance = 0.0;
    s.transmittance = 1.0;
    return s;
}

// Distance along the view to the ground, for a view below the horizon: the near root of
// |x + t v| = Rg, -r mu - sqrt(r^2 mu^2 - rho^2).
float hillaireDistanceToGround(HillaireView v) { return max(-v.r * v.mu - sqrt(max(v.r * v.r * v.mu * v.mu - v.rho2, 0.0)), 0.0); }
bool hillaireViewMeetsGround(HillaireView v) { return v.mu < -sqrt(v.rho2) / v.r; }
// Where the view ends: the ground, or the top of the atmosphere.
float hillaireViewLength(AtmosphereConstants a, HillaireView v) {
    return hillaireViewMeetsGround(v) ? hillaireDistanceToGround(v) : hillaireDistanceToTop(a, v.r, v.mu);
}

// Continues `segment` over [t0, t1] of the view in `steps` steps, equal or growing (`squared`).
HillaireSegment hillaireMarch(AtmosphereConstants a, HillaireConstants c, Texture2D<float4> transmittanceTable, Texture2D<float4> multipleScatteringTable,
                              SamplerState s, HillaireView v, float t0, float t1, int steps, bool squared, HillaireSegment segment) {
    float n = max(steps, 1);
    float rayleigh = rayleighPhase(v.nu), mie = miePhase(v.nu, a.mieScattering.w);
    float start = t0;
    for (int i = 0; i < steps; ++i) {
        float f = (i + 1) / n;
        float end = t0 + (t1 - t0) * (squared ? f * f : f);
        float dt = end - start;
        float t = 0.5 * (start + end);
        start = end;
        float h = altitudeAlongRay(a, v.r, v.rho2, v.mu, t);
        float ry = a.earth.x + h;
        float muS = clamp((v.r * v.muS + t * v.nu) / ry, -1.0, 1.0);  // (x + t v) . s / |x + t v|
        float3 density = particleDensity(a, h);
        float3 sigmaR = a.rayleighScattering.rgb * density.x, sigmaM = a.mieScattering.rgb * density.y;
        float3 extinction = opticalDepth(a, density);  // per metre
        float3 sunT = hillaireTransmittanceToTop(a, c, transmittanceTable, s, ry, muS);
        float3 psi = hillaireMultipleScatteringAt(a, c, multipleScatteringTable, s, ry, muS);
        float3 source = (sigmaR * rayleigh + sigmaM * mie) * sunT + (sigmaR + sigmaM) * psi;
        float3 stepT = exp(-extinction * dt);
        float3 across = extinction > 1e-20 ? (1.0 - stepT) / max(extinction, 1e-20) : dt;  // integral of T over the step
        segment.radiance += segment.transmittance * source * across;
        segment.transmittance *= stepT;
    }
    return segment;
}

#endif
