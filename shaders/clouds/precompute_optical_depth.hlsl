// The particle's optical depth table (optical_depth_table.hlsli), a slab of z slices per unit of
// work: each texel marches its ray's chord through the unit sphere at `steps` midpoints and keeps
// the mean density (Yusov 2014, "Pre-computing optical depth", T = integral of beta over the
// chord, here divided by the chord's length and the particle's density scale).
#include "clouds/cloud_structures.hlsli"
#include "clouds/optical_depth_table.hlsli"
#include "clouds/particle_density.hlsli"

cbuffer ParticleTableBuffer : register(b0) { ParticleTableConstants particleTable; };

RWTexture3D<float> tableOut : register(u0);

[numthreads(8, 8, 1)]
void main(uint3 id : SV_DispatchThreadID) {
    uint4 n = particleTable.sizes;  // N0 (theta_s), N1 (phi_s), N2 (theta_d), N3 (phi_d)
    uint z = id.z + particleTable.options.z;
    if (id.x >= n.y || id.y >= n.x || z >= n.z * n.w) return;
    float4 u = (float4(id.y, id.x, z % n.z, z / n.z) + 0.5) / float4(n);
    float3 s, d;
    opticalDepthRay(u, s, d);
    float chord = 2.0 * dot(-s, d);  // |s + t d| = 1 again at t = -2 s.d
    uint steps = particleTable.options.y;
    float sum = 0.0;
    for (uint k = 0; k < steps; ++k) sum += particleDensity(s + d * (chord * (float(k) + 0.5) / float(steps)), particleTable.options.x);
    tableOut[uint3(id.xy, z)] = sum / float(steps);
}
