// Hillaire 2020's transmittance table: T(r, mu) = exp(-optical depth) from radius r along the
// zenith cosine mu to the top of the atmosphere, at each texel's (r, mu) by Bruneton 2017's
// mapping (parameterization.hlsli), by Simpson's rule over 500 steps (the trapezoidal rule's
// error, (dt / H)^2 / 12 of the aerosols' optical depth, reached 1e-4 of T near the ground). No ray of the table
// meets the ground: mu runs from the zenith to the horizon.
#include "atmosphere/hillaire/precompute_common.hlsli"

RWTexture2D<float4> transmittance : register(u0);

static const int kSteps = 500;

[numthreads(8, 8, 1)]
void main(uint3 id : SV_DispatchThreadID) {
    float2 size = hillaire.transmittanceSize.xy;
    if (id.x >= (uint)size.x || id.y >= (uint)size.y) return;
    float2 rmu = hillaireTransmittanceCoordinates(atmosphere, texelUnit(id.xy, size));
    float r = rmu.x, mu = rmu.y;
    float rho2 = hillaireHorizonDistanceSquared(atmosphere, r);
    float dt = hillaireDistanceToTop(atmosphere, r, mu) / kSteps;
    // Weights 1, 4, 2, 4, ..., 4, 1 (kSteps even), times dt / 3.
    float3 net = particleDensity(atmosphere, r - atmosphere.earth.x) + particleDensity(atmosphere, altitudeAlongRay(atmosphere, r, rho2, mu, kSteps * dt));
    for (int i = 1; i < kSteps; ++i) net += (i % 2 == 1 ? 4.0 : 2.0) * particleDensity(atmosphere, altitudeAlongRay(atmosphere, r, rho2, mu, i * dt));
    transmittance[id.xy] = float4(exp(-opticalDepth(atmosphere, net * (dt / 3.0))), 1.0);
}
