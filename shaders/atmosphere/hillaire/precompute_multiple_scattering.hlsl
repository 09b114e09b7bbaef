// Hillaire 2020's multiple-scattering table Psi_ms(r, mu_s) (Hillaire 2020, section 5.5): at the
// texel's point with the sun at zenith cosine mu_s, over directions spread evenly on the sphere
// (the tables' spherical Fibonacci set, src/tables/SphereDirections), each ray marched in equal steps to the ground or the top, with an
// isotropic phase p_u from the first event of the second order on and the ground black:
//   L_2  = sum of p_u dw  integral of sigma_s T(x, y) T_sun(y) p_u dt  (first-order light at x),
//   f_ms = sum of p_u dw  integral of sigma_s T(x, y) dt                (an isotropic field's share sent back),
//   Psi_ms = L_2 / (1 - f_ms).
// T(x, y) by the trapezoidal rule on four sub-steps a step; T_sun(y) from the transmittance
// table, zero where the Earth hides the sun. The CPU twin: src/reference/HillaireMultipleScatteringTwin.
#include "atmosphere/hillaire/lookup.hlsli"
#include "atmosphere/hillaire/precompute_common.hlsli"

Texture2D<float4> transmittanceTable : register(t0);
StructuredBuffer<float4> sphereDirections : register(t1);  // multipleScatteringSize.z of them
RWTexture2D<float4> multipleScattering : register(u0);

static const float kIsotropicPhase = 1.0 / (4.0 * kPi);
static const int kSubsteps = 4;

// The sun's transmittance at p (radius |p|), from the table; zero behind the Earth.
float3 sunTransmittanceAt(float3 p, float3 sunDir) {
    float r = length(p);
    return hillaireTransmittanceToTop(atmosphere, hillaire, transmittanceTable, linearClamp, r, dot(p, sunDir) / r);
}

[numthreads(8, 8, 1)]
void main(uint3 id : SV_DispatchThreadID) {
    float2 size = hillaire.multipleScatteringSize.xy;
    if (id.x >= (uint)size.x || id.y >= (uint)size.y) return;
    float2 rmuS = hillaireMultipleScatteringCoordinates(atmosphere, texelUnit(id.xy, size));
    float r = rmuS.x, muS = rmuS.y;
    float3 x = float3(0.0, r, 0.0), sunDir = float3(sqrt(max(0.0, 1.0 - muS * muS)), muS, 0.0);
    int directions = (int)hillaire.multipleScatteringSize.z, steps = (int)hillaire.multipleScatteringSize.w;
    float rho2 = hillaireHorizonDistanceSquared(atmosphere, r);
    float3 secondOrder = 0.0, transfer = 0.0;
    for (int i = 0; i < directions; ++i) {
        float3 w = sphereDirections[i].xyz;
        // To the ground below the horizon (none from the ground itself), else to the top.
        bool toGround = w.y < -sqrt(rho2) / r;
        float rayLength = toGround ? max(raySphere(x, w, atmosphere.earth.x).x, 0.0) : max(raySphere(x, w, atmosphere.earth.z).y, 0.0);
        float dt = rayLength / steps, h = dt / kSubsteps;
        float3 net = 0.0;
        float3 density = particleDensity(atmosphere, r - atmosphere.earth.x);
        float3 l2 = 0.0, f = 0.0;
        for (int s = 0; s < steps; ++s) {
            // Up to the step's middle, then past it to its end: the sample at the middle.
            for (int k = 1; k <= kSubsteps; ++k) {
                float t = (s * kSubsteps + k) * h;
                float3 next = particleDensity(atmosphere, altitudeAlongRay(atmosphere, r, rho2, w.y, t));
                net += (density + next) * (0.5 * h);
                density = next;
                if (2 * k == kSubsteps) {
                    float3 y = x + w * t;
                    float3 scattered = scatteringAt(length(y) - atmosphere.earth.x) * exp(-opticalDepth(atmosphere, net)) * dt;
                    f += scattered;
                    l2 += scattered * sunTransmittanceAt(y, sunDir) * kIsotropicPhase;
                }
            }
        }
        secondOrder += l2;
        transfer += f;
    }
    float weight = kIsotropicPhase * 4.0 * kPi / directions;
    secondOrder *= weight;
    transfer *= weight;
    multipleScattering[id.xy] = float4(secondOrder / (1.0 - transfer), 1.0);
}
