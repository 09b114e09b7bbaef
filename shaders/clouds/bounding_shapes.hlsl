// Show particles: bounding shapes. Each particle drawn as its ellipsoid (horizontal radius about
// the planet's normal, vertical radius along it), lit by the sun with a flat ambient and tinted
// by its ring, with its true depth, over the scene (docs/clouds.md, "Show particles").
#include "clouds/particle_shape.hlsli"

ShapeVertex vs_main(uint vertexId : SV_VertexID, uint instance : SV_InstanceID) { return shapeVertex(vertexId, instance); }

float4 ps_main(ShapeVertex input, out float depth : SV_Depth) : SV_Target {
    CloudParticle p = particles[input.slot];
    float3 direction = pixelDirection(input.position, frame.screen.zw);
    ParticleHit hit;
    if (!hitParticle(p, direction, hit)) discard;
    float t = hit.near >= 0.0 ? hit.near : hit.far;  // the camera inside: the far side
    float3 local = (frame.cameraPosition.xyz - p.centre.xyz + t * direction);
    local = float3(dot(local, hit.tangent), dot(local, hit.normal), dot(local, hit.bitangent)) / hit.scale;  // on the unit sphere
    float3 worldNormal = normalize((local.x / hit.scale.x) * hit.tangent + (local.y / hit.scale.y) * hit.normal + (local.z / hit.scale.z) * hit.bitangent);
    float4 clip = mul(frame.viewProjection, float4(frame.cameraPosition.xyz + t * direction, 1.0));
    depth = saturate(clip.z / clip.w);
    // Rings alternate between two tints, so that their boundaries show.
    float3 albedo = (uint(p.shape.w) & 1u) ? float3(0.85, 0.75, 0.6) : float3(0.6, 0.75, 0.9);
    float lambert = max(dot(worldNormal, frame.directionToSun.xyz), 0.0);
    return float4(albedo / 3.14159265 * frame.sunIrradiance.rgb * (lambert + 0.15), 1.0);
}
