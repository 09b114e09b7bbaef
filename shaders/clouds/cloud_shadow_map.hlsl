// The clouds' light-space transparency maps (Yusov 2014, "Integration with light scattering";
// docs/clouds.md, "Shadows and shafts from clouds"): every particle drawn from the sun as the
// square around its bounding sphere, orthographically, into a map centred over the camera (one
// slice of the maps' array per draw; the constants' centre is that map's). Each
// texel's pixel follows the sun's ray through it into the particle's ellipsoid and writes
// (far, -near, 0, T): where the chord leaves and enters, as distances toward the sun from the
// map's centre, and the chord's transmittance e^(-tau) from the optical depth table. The blend
// keeps the smallest of the first two (the clouds' farthest exit and nearest entry on the ray)
// and multiplies the transmittances, so the order of the particles does not matter. Readers:
// shadows/cloud_shadow.hlsli.
#define FIRMAMENT_CLOUD_SHADOW_WRITER
#include "clouds/optical_depth_table.hlsli"
#include "clouds/particle_shape.hlsli"
#include "shadows/shadow_structures.hlsli"

cbuffer CloudShadowBuffer : register(b2) { CloudShadowConstants cloudShadow; };
#include "shadows/cloud_shadow.hlsli"
Texture3D<float> opticalDepthTable : register(t2);
SamplerState linearWrap : register(s0);

ShapeVertex vs_main(uint vertexId : SV_VertexID, uint instance : SV_InstanceID) {
    ShapeVertex output;
    output.slot = sortedKeys[instance].y;
    CloudParticle p = particles[output.slot];
    float radius = max(p.centre.w, p.shape.x) / cloudShadow.centre.w;
    float2 corner = float2(vertexId & 1u, vertexId >> 1) * 2.0 - 1.0;
    output.position = float4(cloudShadowPositionIn(0, p.centre.xyz) + corner * radius, 0.5, 1.0);
    return output;
}

float4 ps_main(ShapeVertex input) : SV_Target {
    float n = cloudShadow.right.w;
    float2 xy = float2(input.position.x / n * 2.0 - 1.0, 1.0 - input.position.y / n * 2.0) * cloudShadow.centre.w;
    CloudParticle q = particles[input.slot];
    float3 sun = cloudShadow.sun.xyz;
    // On the texel's sun ray, a little nearer the sun than the particle.
    float above = cloudShadowHeightIn(0, q.centre.xyz) + 2.0 * max(q.centre.w, q.shape.x);
    float3 origin = cloudShadow.centre.xyz + xy.x * cloudShadow.right.xyz + xy.y * cloudShadow.up.xyz + sun * above;
    ParticleHit hit;
    if (!hitParticleFrom(q, origin, -sun, hit)) discard;
    float entry = max(hit.near, 0.0);
    float length = hit.far - entry;
    if (length <= 0.0) discard;
    float opticalDepth = particleOpticalDepth(q, hit, length, opticalDepthTable, linearWrap);
    return float4(above - hit.far, -(above - entry), 0.0, exp(-opticalDepth));
}
