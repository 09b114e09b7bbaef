// Pre-computation, step 1: the net density (density integrated over length) of air, aerosols
// and ozone from every altitude to the top of the atmosphere along every zenith angle, by
// Simpson's rule, in blocks of rows. Its optical depth gives the sun's transmittance anywhere (Yusov 2013,
// "Terrain shaders"). Rays that hit the ground store the grazing ray's value (lut_lookup.hlsli).
#include "atmosphere/yusov/parameterization.hlsli"

cbuffer AtmosphereBuffer : register(b0) {
    AtmosphereConstants atmosphere;
};
cbuffer SliceBuffer : register(b1) {
    PrecomputeSliceConstants slab;  // rows of altitude this dispatch fills
};

RWTexture2D<float4> netDensity : register(u0);  // x: zenith cosine, y: altitude

static const int kSimpsonIntervals = 128;  // even

float3 netDensityAlongRay(float h, float cosZenith) {
    cosZenith = max(cosZenith, cosHorizon(atmosphere, h));
    float3 origin = float3(0.0, atmosphere.earth.x + h, 0.0);
    float3 dir = float3(sqrt(saturate(1.0 - cosZenith * cosZenith)), cosZenith, 0.0);
    float rayLength = max(raySphere(origin, dir, atmosphere.earth.z).y, 0.0);
    float step = rayLength / kSimpsonIntervals;
    float3 sum = 0.0;
    for (int i = 0; i <= kSimpsonIntervals; ++i) {
        float weight = (i == 0 || i == kSimpsonIntervals) ? 1.0 : ((i & 1) ? 4.0 : 2.0);
        float altitude = max(length(origin + dir * (i * step)) - atmosphere.earth.x, 0.0);
        sum += weight * particleDensity(atmosphere, altitude);
    }
    return sum * step / 3.0;
}

[numthreads(8, 8, 1)]
void main(uint3 id : SV_DispatchThreadID) {
    float2 n = atmosphere.netDensityLutSize.xy;
    uint2 texel = uint2(id.x, id.y + slab.range.x);
    if (texel.x >= (uint)n.y || texel.y >= slab.range.y) return;
    float cosZenith = texel.x / (n.y - 1.0) * 2.0 - 1.0;
    float h = unitToAltitude(atmosphere, texel.y / (n.x - 1.0));
    netDensity[texel] = float4(netDensityAlongRay(h, cosZenith), 0.0);
}
