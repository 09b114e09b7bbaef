// Bruneton and Neyret 2008, the ground irradiance tables (Bruneton and Neyret 2008, "Irradiance",
// "Multiple Irradiance Table"), per unit sun irradiance on a horizontal surface at radius r
// with the sun at zenith cosine mu_s:
//   direct:     delta E = T(r, mu_s) max(mu_s, 0), the sun's light alone;
//   indirect:   delta E = integral over the upper hemisphere of L(r, w, mu_s) (w . n) dw for the
//               light of the previous order (its Rayleigh and Mie parts times their phase
//               functions when that order is the first);
//   accumulate: E += delta E: the sky's light of every order, the table render.hlsl reads.
#include "atmosphere/bruneton/precompute_common.hlsli"

bool irradianceThread(uint3 id, out float r, out float muS) {
    r = 0.0;
    muS = 0.0;
    if (id.x >= (uint)bruneton.irradianceSize.x || id.y >= (uint)bruneton.irradianceSize.y) return false;
    irradianceTexel(atmosphere, bruneton, id.xy, r, muS);
    return true;
}

// ---- direct ----
Texture2D<float4> transmittanceTable : register(t0);
RWTexture2D<float4> deltaIrradiance : register(u0);

[numthreads(8, 8, 1)]
void direct(uint3 id : SV_DispatchThreadID) {
    float r, muS;
    if (!irradianceThread(id, r, muS)) return;
    deltaIrradiance[id.xy] = float4(sunTransmittanceAt(atmosphere, bruneton, transmittanceTable, linearClamp, r, muS) * max(muS, 0.0), 0.0);
}

// ---- indirect ----
Texture3D<float4> deltaRayleigh : register(t1);  // the previous order (all of it from order 2 on)
Texture3D<float4> deltaMie : register(t2);       // single Mie scattering (order 1 only)
StructuredBuffer<float4> sphereDirections : register(t3);

[numthreads(8, 8, 1)]
void indirect(uint3 id : SV_DispatchThreadID) {
    float r, muS;
    if (!irradianceThread(id, r, muS)) return;
    float3 sun = float3(sqrt(saturate(1.0 - muS * muS)), muS, 0.0);
    bool firstOrder = bruneton.ground.y < 2.5;  // delta S holds order 1 while order 2's irradiance is computed
    uint count = (uint)atmosphere.netDensityLutSize.w;
    float3 sum = 0.0;
    for (uint i = 0; i < count; ++i) {
        float3 w = sphereDirections[i].xyz;
        if (w.y <= 0.0) continue;
        float nu = dot(sun, w);
        float4 rayleigh = sampleInscatter(atmosphere, bruneton, deltaRayleigh, linearClamp, r - atmosphere.earth.x, w.y, muS, nu, false);
        float3 light = rayleigh.rgb;
        if (firstOrder) {
            float4 mie = sampleInscatter(atmosphere, bruneton, deltaMie, linearClamp, r - atmosphere.earth.x, w.y, muS, nu, false);
            light = rayleigh.rgb * rayleighPhase(nu) + mie.rgb * miePhase(nu, atmosphere.mieScattering.w);
        }
        sum += light * w.y;
    }
    deltaIrradiance[id.xy] = float4(sum * (4.0 * kPi / count), 0.0);
}

// ---- accumulate ----
Texture2D<float4> irradianceSoFar : register(t0);
Texture2D<float4> deltaIrradianceIn : register(t1);
RWTexture2D<float4> irradiance : register(u0);

[numthreads(8, 8, 1)]
void accumulate(uint3 id : SV_DispatchThreadID) {
    float r, muS;
    if (!irradianceThread(id, r, muS)) return;
    irradiance[id.xy] = irradianceSoFar[id.xy] + deltaIrradianceIn[id.xy];
}
