// Bruneton and Neyret 2008, the 4D in-scatter tables (Bruneton and Neyret 2008, "Single Inscatter Table",
// "Multiple Inscatter Table"), one thread per texel of the packed 3D texture, in slabs of
// radius layers (PrecomputeSliceConstants), per unit sun irradiance:
//   singleScattering: delta S_R = beta_R integral of rho_R(y) T(x -> y) T_sun(y) dt, delta S_M likewise
//            with beta_M and rho_M: order 1 without its phase functions;
//   initial: S = (delta S_R, red of delta S_M): Rayleigh in RGB, Mie's red in alpha;
//   scatteredRadiance: delta J(x, v) = integral over the sphere of
//            [albedo / pi delta E(g) T(x -> g) if w meets the ground at g, plus delta S(x, w)]
//            (beta_R rho_R P_R(v . w) + beta_M rho_M P_M(v . w)) dw   (the paper's eq. 7, with
//            the ground's bounce), where delta E is the irradiance reaching the ground from the
//            previous order (the sun's own for order 2);
//   order:   delta S(x, v) = integral of T(x -> y) delta J(y, v) dt     (order n);
//   accumulate: S.rgb += delta S / P_R(nu), so that render time's S.rgb P_R(nu) gives it back.
// S itself holds its light times kInscatterScale (lookup.hlsli says why); the deltas are float32, unscaled.
// The sphere integrals use the same equal-area directions as Yusov's model (sphereDirections).
#include "atmosphere/bruneton/precompute_common.hlsli"

static const int kSingleSteps = 128;
static const int kOrderSteps = 64;

Texture2D<float4> transmittanceTable : register(t0);

// A march along the texel's ray by the trapezoidal rule: where step i lands (altitude, radius,
// zenith cosines of the view and the sun there) and the transmittance from the texel to it,
// from the density integrated so far.
struct MarchPoint {
    float h, r, mu, muS;
    float3 transmittance;
};
struct March {
    InscatterSample s;
    float dt;
    float3 net, density;  // density integrated from the start; density at the last point
};

March startMarch(InscatterSample s, int steps) {
    March m;
    m.s = s;
    m.dt = rayLength(s.r, s.rho2, s.mu, s.groundHalf) / steps;
    m.net = 0.0;
    m.density = particleDensity(atmosphere, s.h);
    return m;
}

MarchPoint marchTo(inout March m, int i) {
    float t = i * m.dt;
    MarchPoint p;
    p.h = altitudeAt(m.s.r, m.s.rho2, m.s.mu, t);
    p.r = atmosphere.earth.x + p.h;
    float3 density = particleDensity(atmosphere, p.h);
    if (i > 0) m.net += (m.density + density) * (0.5 * m.dt);
    m.density = density;
    p.mu = clamp((m.s.r * m.s.mu + t) / p.r, -1.0, 1.0);
    p.muS = clamp((m.s.nu * t + m.s.muS * m.s.r) / p.r, -1.0, 1.0);
    p.transmittance = exp(-opticalDepth(atmosphere, m.net));
    return p;
}

// ---- singleScattering ----
RWTexture3D<float4> deltaRayleighOut : register(u0);
RWTexture3D<float4> deltaMieOut : register(u1);

[numthreads(8, 8, 1)]
void singleScattering(uint3 id : SV_DispatchThreadID) {
    uint3 texel;
    InscatterSample s;
    if (!inscatterThread(id, texel, s)) return;
    March m = startMarch(s, kSingleSteps);
    float3 rayleigh = 0.0, mie = 0.0, previousR = 0.0, previousM = 0.0;
    for (int i = 0; i <= kSingleSteps; ++i) {
        MarchPoint p = marchTo(m, i);
        float3 light = p.transmittance * sunTransmittanceAt(atmosphere, bruneton, transmittanceTable, linearClamp, p.r, p.muS);
        float3 r = m.density.x * light, mi = m.density.y * light;
        if (i > 0) {
            rayleigh += (previousR + r) * (0.5 * m.dt);
            mie += (previousM + mi) * (0.5 * m.dt);
        }
        previousR = r;
        previousM = mi;
    }
    deltaRayleighOut[texel] = float4(rayleigh * atmosphere.rayleighScattering.rgb, 0.0);
    deltaMieOut[texel] = float4(mie * atmosphere.mieScattering.rgb, 0.0);
}

// ---- initial ----
Texture3D<float4> deltaRayleigh : register(t1);
Texture3D<float4> deltaMie : register(t2);
RWTexture3D<float4> inscatterOut : register(u0);

[numthreads(8, 8, 1)]
void initial(uint3 id : SV_DispatchThreadID) {
    uint3 texel;
    InscatterSample s;
    if (!inscatterThread(id, texel, s)) return;
    inscatterOut[texel] = float4(deltaRayleigh[texel].rgb, deltaMie[texel].r) * kInscatterScale;
}

// ---- scatteredRadiance ----
Texture2D<float4> deltaIrradiance : register(t3);  // reaching the ground from the previous order
StructuredBuffer<float4> sphereDirections : register(t4);
RWTexture3D<float4> deltaJOut : register(u0);

[numthreads(8, 8, 1)]
void scatteredRadiance(uint3 id : SV_DispatchThreadID) {
    uint3 texel;
    InscatterSample s;
    if (!inscatterThread(id, texel, s)) return;
    float rg = atmosphere.earth.x;
    // The frame: x straight above the centre, y up, the view in the x-y plane.
    float sinView = sqrt(saturate(1.0 - s.mu * s.mu));
    float3 view = float3(sinView, s.mu, 0.0);
    float sunX = sinView > 1e-6 ? (s.nu - s.mu * s.muS) / sinView : 0.0;
    float3 sun = float3(sunX, s.muS, sqrt(saturate(1.0 - sunX * sunX - s.muS * s.muS)));
    float3 density = particleDensity(atmosphere, s.r - rg);
    float g = atmosphere.mieScattering.w;
    bool secondOrder = bruneton.ground.y < 2.5;
    float albedo = bruneton.ground.x;
    float cosHorizonHere = -sqrt(s.rho2) / s.r;
    uint count = (uint)atmosphere.netDensityLutSize.w;
    float3 sum = 0.0;
    for (uint i = 0; i < count; ++i) {
        float3 w = sphereDirections[i].xyz;
        bool toGround = w.y < cosHorizonHere;
        float3 incoming = 0.0;
        if (toGround && albedo > 0.0) {
            float d = distanceToGround(s.r, w.y, s.rho2);
            float3 groundNormal = (float3(0.0, s.r, 0.0) + d * w) / rg;
            float3 e = irradianceAt(atmosphere, bruneton, deltaIrradiance, linearClamp, rg, dot(groundNormal, sun));
            incoming = albedo / kPi * e * transmittanceAlong(atmosphere, bruneton, transmittanceTable, linearClamp, s.r, w.y, d);
        }
        float nu1 = dot(sun, w);
        float4 rayleigh = sampleInscatter(atmosphere, bruneton, deltaRayleigh, linearClamp, s.h, w.y, s.muS, nu1, toGround);
        if (secondOrder) {
            float4 mie = sampleInscatter(atmosphere, bruneton, deltaMie, linearClamp, s.h, w.y, s.muS, nu1, toGround);
            incoming += rayleigh.rgb * rayleighPhase(nu1) + mie.rgb * miePhase(nu1, g);
        } else {
            incoming += rayleigh.rgb;
        }
        float nu2 = dot(view, w);
        sum += incoming * (atmosphere.rayleighScattering.rgb * density.x * rayleighPhase(nu2) +
                           atmosphere.mieScattering.rgb * density.y * miePhase(nu2, g));
    }
    deltaJOut[texel] = float4(sum * (4.0 * kPi / count), 0.0);
}

// ---- order ----
Texture3D<float4> deltaJ : register(t1);
RWTexture3D<float4> deltaScatteringOut : register(u0);

[numthreads(8, 8, 1)]
void order(uint3 id : SV_DispatchThreadID) {
    uint3 texel;
    InscatterSample s;
    if (!inscatterThread(id, texel, s)) return;
    March m = startMarch(s, kOrderSteps);
    float3 result = 0.0, previous = 0.0;
    for (int i = 0; i <= kOrderSteps; ++i) {
        MarchPoint p = marchTo(m, i);
        float3 current = p.transmittance * sampleInscatter(atmosphere, bruneton, deltaJ, linearClamp, p.h, p.mu, p.muS, s.nu, s.groundHalf).rgb;
        if (i > 0) result += (previous + current) * (0.5 * m.dt);
        previous = current;
    }
    deltaScatteringOut[texel] = float4(result, 0.0);
}

// ---- accumulate ----
Texture3D<float4> inscatterSoFar : register(t1);
Texture3D<float4> deltaScattering : register(t2);

[numthreads(8, 8, 1)]
void accumulate(uint3 id : SV_DispatchThreadID) {
    uint3 texel;
    InscatterSample s;
    if (!inscatterThread(id, texel, s)) return;
    inscatterOut[texel] = inscatterSoFar[texel] + float4(deltaScattering[texel].rgb * (kInscatterScale / rayleighPhase(s.nu)), 0.0);
}
