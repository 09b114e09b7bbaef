// Pre-computation, step 6: the ambient sky light (Yusov 2013, eq. 3), the irradiance the
// whole sky gives a horizontal surface on the ground per unit sun irradiance, for each cosine
// of the sun's zenith angle (-1 .. 1 at texel centres):
//   E_sky(phi) = integral over the upper hemisphere of L^M(C, w, l(phi)) (w . N) dw,
// with the uniform directions of the sphere folded into the upper half (2 pi / N each).
#include "atmosphere/yusov/lookup.hlsli"

cbuffer AtmosphereBuffer : register(b0) {
    AtmosphereConstants atmosphere;
};

Texture3D<float4> multipleTable : register(t0);
StructuredBuffer<float4> sphereDirections : register(t1);
SamplerState linearClamp : register(s0);
RWTexture2D<float4> ambientLight : register(u0);  // width: sun zenith; height 1

static const float kGroundAltitude = 1.0;  // metres: just above the ground, clear of the horizon's ambiguity

[numthreads(64, 1, 1)]
void main(uint3 id : SV_DispatchThreadID) {
    float width = atmosphere.netDensityLutSize.z;
    if (id.x >= (uint)width) return;
    float cosSun = id.x / (width - 1.0) * 2.0 - 1.0;
    float3 sunDir = float3(sqrt(saturate(1.0 - cosSun * cosSun)), cosSun, 0.0);
    float3 position = float3(0.0, atmosphere.earth.x + kGroundAltitude, 0.0);
    uint count = (uint)atmosphere.netDensityLutSize.w;
    float3 irradiance = 0.0;
    for (uint i = 0; i < count; ++i) {
        float3 w = sphereDirections[i].xyz;
        w.y = abs(w.y);
        int side = kHorizonUndecided;
        irradiance += lookUpSpeciesScattering(atmosphere, multipleTable, linearClamp, position, w, sunDir, side) * w.y;
    }
    ambientLight[id.xy] = float4(irradiance * (2.0 * kPi / count), 0.0);
}
