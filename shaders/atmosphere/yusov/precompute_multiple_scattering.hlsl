// Pre-computation, steps 3 to 5: multiple scattering (Yusov 2013, "Multiple scattering",
// after Bruneton and Neyret 2008, without the ground's reflection). For each order n = 2..N:
//   scatteredRadiance: J^(n)(P, v, l) = sum over species of beta rho(h) integral over the sphere
//       of p(v . w) L^(n-1)(P, w, l) dw  (eq. 1; 4 pi / N per direction of a uniform set);
//   scatteringOrder:   L^(n)(C, v, l) = integral over the view ray of T(C -> P) J^(n)(P, v, l) ds
//       (eq. 2, trapezoidal), and the high-order sum L^H += L^(n);
// then combine: L^M = L^(1) + L^H. Every table is 4D packed into 3D, one thread per texel, in
// slabs of z (PrecomputeSliceConstants); the single and all-orders tables hold a bank of texels
// per species (lookup.hlsli). Every table, J's too, holds its light times kTableScale: the texels
// read with Load stay in those units, those read by look-up come out of them.
#include "atmosphere/yusov/lookup.hlsli"
#include "atmosphere/yusov/single_scattering.hlsli"

cbuffer AtmosphereBuffer : register(b0) {
    AtmosphereConstants atmosphere;
};
cbuffer SliceBuffer : register(b1) {
    PrecomputeSliceConstants slab;
};

SamplerState linearClamp : register(s0);

static const int kOrderIntegrationSteps = 64;

// This dispatch's texel's ray (TexelRay, scattering_parameterization.hlsli); false outside the slab.
bool texelRay(uint3 id, out TexelRay ray) {
    uint3 texel = id + uint3(0, 0, slab.range.x);
    float4 n = atmosphere.scatteringLutSize;
    ray = (TexelRay)0;
    if (texel.x >= (uint)n.x || texel.y >= (uint)n.y || texel.z >= slab.range.y) return false;
    ray = texelRay(atmosphere, texel);
    return true;
}

uint3 texelOf(uint3 id) { return id + uint3(0, 0, slab.range.x); }

// ---- J^(n) ----
Texture3D<float4> previousOrder : register(t0);
StructuredBuffer<float4> sphereDirections : register(t1);
RWTexture3D<float4> scattered : register(u0);

// J^(n) at this dispatch's texel; order n - 1 is the single scattering table of species when
// `fromSingle` (n = 2), a table of radiance after.
void gatherScattered(uint3 id, bool fromSingle) {
    TexelRay ray;
    if (!texelRay(id, ray)) return;
    float3 density = particleDensity(atmosphere, ray.altitude);
    uint count = (uint)atmosphere.netDensityLutSize.w;
    float3 sum = 0.0;
    for (uint i = 0; i < count; ++i) {
        float3 w = sphereDirections[i].xyz;
        int side = kHorizonUndecided;
        float3 incoming = fromSingle ? lookUpSpeciesScattering(atmosphere, previousOrder, linearClamp, ray.start, w, ray.sunDir, side)
                                     : lookUpScattering(atmosphere, previousOrder, linearClamp, ray.start, w, ray.sunDir, side);
        sum += scatteringCoefficient(atmosphere, density, dot(ray.viewDir, w)) * incoming;
    }
    scattered[texelOf(id)] = float4(sum * (4.0 * kPi / count) * kTableScale, 0.0);
}

[numthreads(4, 8, 4)]
void scatteredRadianceFromSingle(uint3 id : SV_DispatchThreadID) { gatherScattered(id, true); }

[numthreads(4, 8, 4)]
void scatteredRadiance(uint3 id : SV_DispatchThreadID) { gatherScattered(id, false); }

// ---- L^(n) and the high-order sum ----
Texture3D<float4> scatteredTable : register(t0);   // J^(n)
Texture3D<float4> highOrderSoFar : register(t2);   // L^H before this order (zero before order 2)
RWTexture3D<float4> order : register(u0);          // L^(n)
RWTexture3D<float4> highOrder : register(u1);      // L^H after it

[numthreads(4, 8, 4)]
void scatteringOrder(uint3 id : SV_DispatchThreadID) {
    TexelRay ray;
    if (!texelRay(id, ray)) return;
    float rayLength = rayLengthInAtmosphere(atmosphere, ray.start, ray.viewDir, ray.belowHorizon);
    float stepLength = rayLength / kOrderIntegrationSteps;
    float3 density = particleDensity(atmosphere, ray.altitude);
    int side = kHorizonUndecided;
    float3 integrand = lookUpScattering(atmosphere, scatteredTable, linearClamp, ray.start, ray.viewDir, ray.sunDir, side);
    float3 netDensityFromStart = 0.0;
    float3 radiance = 0.0;
    for (int i = 1; i <= kOrderIntegrationSteps; ++i) {
        float3 position = ray.start + ray.viewDir * (i * stepLength);
        float3 nextDensity = particleDensity(atmosphere, length(position) - atmosphere.earth.x);
        netDensityFromStart += (density + nextDensity) * (0.5 * stepLength);
        side = kHorizonUndecided;
        float3 nextIntegrand = exp(-opticalDepth(atmosphere, netDensityFromStart)) *
                               lookUpScattering(atmosphere, scatteredTable, linearClamp, position, ray.viewDir, ray.sunDir, side);
        radiance += (integrand + nextIntegrand) * (0.5 * stepLength);
        density = nextDensity;
        integrand = nextIntegrand;
    }
    uint3 texel = texelOf(id);
    order[texel] = float4(radiance * kTableScale, 0.0);
    highOrder[texel] = float4(highOrderSoFar.Load(int4(texel, 0)).rgb + radiance * kTableScale, 0.0);
}

// ---- L^M = L^(1) + L^H ----
// A table of species like the single scattering table: S_R + L^H / P_R(v.l) in the Rayleigh bank
// (P_R at the texel's own sun-view angle), S_M in the Mie bank, so that lookUpSpeciesScattering
// gives P_R S_R + P_M S_M + L^H.
Texture3D<float4> singleTable : register(t0);
Texture3D<float4> highOrderTable : register(t2);
RWTexture3D<float4> multiple : register(u0);

[numthreads(4, 8, 4)]
void combine(uint3 id : SV_DispatchThreadID) {
    TexelRay ray;
    if (!texelRay(id, ray)) return;
    int4 texel = int4(texelOf(id), 0);
    int4 mieTexel = texel + int4((int)atmosphere.scatteringLutSize.x, 0, 0, 0);
    float phase = rayleighPhase(dot(ray.viewDir, ray.sunDir));
    multiple[texel.xyz] = float4(singleTable.Load(texel).rgb + highOrderTable.Load(texel).rgb / phase, 0.0);
    multiple[mieTexel.xyz] = singleTable.Load(mieTexel);
}
