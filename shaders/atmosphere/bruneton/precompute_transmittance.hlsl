// Bruneton and Neyret 2008, pre-computation step 1 (Bruneton and Neyret 2008, "Transmittance Table"):
// T(r, mu) = exp(-sum of beta_e integral of rho(h) ds) from radius r to the top of the atmosphere
// along zenith cosine mu, by the trapezoidal rule. Rays that meet the ground take the grazing
// ray's value (see lookup.hlsli), so that filtering never blurs the horizon.
#include "atmosphere/bruneton/precompute_common.hlsli"

RWTexture2D<float4> transmittance : register(u0);

static const int kSteps = 500;

[numthreads(8, 8, 1)]
void main(uint3 id : SV_DispatchThreadID) {
    if (id.x >= (uint)bruneton.transmittanceSize.x || id.y >= (uint)bruneton.transmittanceSize.y) return;
    float r, mu;
    transmittanceTexel(atmosphere, bruneton, id.xy, r, mu);
    mu = max(mu, cosHorizonAtRadius(atmosphere, r));
    float rho2 = rho2At(atmosphere, r - atmosphere.earth.x);
    float pathLength = rayLength(r, rho2, mu, false);
    float dt = pathLength / kSteps;
    float3 density = particleDensity(atmosphere, r - atmosphere.earth.x);
    float3 net = 0.0;
    for (int i = 1; i <= kSteps; ++i) {
        float3 next = particleDensity(atmosphere, altitudeAt(r, rho2, mu, i * dt));
        net += (density + next) * (0.5 * dt);
        density = next;
    }
    transmittance[id.xy] = float4(exp(-opticalDepth(atmosphere, net)), 0.0);
}
