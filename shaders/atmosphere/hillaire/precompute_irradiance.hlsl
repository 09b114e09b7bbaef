// The sky's irradiance on a horizontal surface, E(r, mu_s) per unit sun irradiance, from Hillaire
// 2020's own radiance: Firmament's addition, so that the ground is lit by the model that draws
// the sky (the paper's ground takes its sky light elsewhere). At the texel's radius with the sun
// at zenith cosine mu_s,
//   E = sum over the upper half of the directions w of L(x, w) (w . up) 4 pi / N,
// L marched (march.hlsli: single scattering and Psi_ms) in irradianceSize.w growing steps to the top. The
// table shares the multiple-scattering table's mapping (u = 0.5 + 0.5 mu_s, v linear in r).
#include "atmosphere/hillaire/march.hlsli"
#include "atmosphere/hillaire/precompute_common.hlsli"

Texture2D<float4> transmittanceTable : register(t0);
Texture2D<float4> multipleScatteringTable : register(t1);
StructuredBuffer<float4> directions : register(t2);  // irradianceSize.z of them over the sphere
RWTexture2D<float4> irradiance : register(u0);

[numthreads(8, 8, 1)]
void main(uint3 id : SV_DispatchThreadID) {
    float2 size = hillaire.irradianceSize.xy;
    if (id.x >= (uint)size.x || id.y >= (uint)size.y) return;
    float2 rmuS = hillaireMultipleScatteringCoordinates(atmosphere, texelUnit(id.xy, size));
    float3 sunDir = float3(sqrt(max(0.0, 1.0 - rmuS.y * rmuS.y)), rmuS.y, 0.0);
    int count = (int)hillaire.irradianceSize.z;
    float3 sum = 0.0;
    for (int i = 0; i < count; ++i) {
        float3 w = directions[i].xyz;
        if (w.y <= 0.0) continue;
        HillaireView v;
        v.r = rmuS.x;
        v.rho2 = hillaireHorizonDistanceSquared(atmosphere, v.r);
        v.mu = w.y;
        v.muS = sunDir.y;
        v.nu = dot(w, sunDir);
        HillaireSegment s = hillaireMarch(atmosphere, hillaire, transmittanceTable, multipleScatteringTable, linearClamp, v, 0.0,
                                          hillaireDistanceToTop(atmosphere, v.r, v.mu), (int)hillaire.irradianceSize.w, true, hillaireEmptySegment());
        sum += s.radiance * w.y;
    }
    irradiance[id.xy] = float4(sum * (4.0 * kPi / count), 1.0);
}
