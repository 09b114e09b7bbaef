// "Show particles": each particle drawn as its bounding shape, an ellipsoid (horizontal radius
// about the planet's normal, vertical radius along it), lit by the sun with a flat ambient and
// tinted by its ring; in back-to-front order, with its true depth, over the scene. A
// camera-facing quad covers the ellipsoid's silhouette; the pixel shader intersects the view ray
// with the ellipsoid (docs/clouds.md, "Show particles").
#include "clouds/cloud_field.hlsli"

StructuredBuffer<uint2> sortedKeys : register(t0);  // y: the particle's slot
StructuredBuffer<CloudParticle> particles : register(t1);

struct ShapeVertex {
    float4 position : SV_Position;
    nointerpolation uint slot : PARTICLE;
};

// The ellipsoid's axes: the planet's normal through its centre and two tangents.
void particleFrame(float3 centre, out float3 tangent, out float3 normal, out float3 bitangent) {
    normal = normalize(centre + float3(0.0, frame.planet.x, 0.0));
    tangent = normalize(cross(normal, float3(0.0, 0.0, 1.0)));
    bitangent = cross(tangent, normal);
}

ShapeVertex vs_main(uint vertexId : SV_VertexID, uint instance : SV_InstanceID) {
    ShapeVertex output;
    output.slot = sortedKeys[instance].y;
    CloudParticle p = particles[output.slot];
    float2 corner = float2(vertexId & 1u, vertexId >> 1) * 2.0 - 1.0;
    float3 toCentre = p.centre.xyz - frame.cameraPosition.xyz;
    float distance = length(toCentre);
    float radius = max(p.centre.w, p.shape.x);  // the bounding sphere's
    if (distance <= radius * 1.05) {
        // The camera is inside or at the bounding sphere: the whole screen, at the near plane.
        output.position = float4(corner, 1.0, 1.0);
        return output;
    }
    float3 forward = toCentre / distance;
    float3 up = abs(forward.y) < 0.99 ? float3(0.0, 1.0, 0.0) : float3(1.0, 0.0, 0.0);
    float3 right = normalize(cross(up, forward));
    up = cross(forward, right);
    // The silhouette's cone meets the plane through the centre in a circle of this radius.
    float extent = radius * distance / sqrt(distance * distance - radius * radius);
    float3 world = p.centre.xyz + (corner.x * right + corner.y * up) * extent;
    output.position = mul(frame.viewProjection, float4(world, 1.0));
    return output;
}

float4 ps_main(ShapeVertex input, out float depth : SV_Depth) : SV_Target {
    CloudParticle p = particles[input.slot];
    float2 ndc = float2(input.position.x * frame.screen.z * 2.0 - 1.0, 1.0 - input.position.y * frame.screen.w * 2.0);
    float4 farPoint = mul(frame.clipToDirection, float4(ndc, 1.0, 1.0));
    float3 direction = normalize(farPoint.xyz / farPoint.w);
    // In the ellipsoid's unit-sphere space: |o + t d|^2 = 1.
    float3 tangent, normal, bitangent;
    particleFrame(p.centre.xyz, tangent, normal, bitangent);
    float3 scale = float3(p.centre.w, p.shape.x, p.centre.w);
    float3 toCamera = frame.cameraPosition.xyz - p.centre.xyz;
    float3 o = float3(dot(toCamera, tangent), dot(toCamera, normal), dot(toCamera, bitangent)) / scale;
    float3 d = float3(dot(direction, tangent), dot(direction, normal), dot(direction, bitangent)) / scale;
    float a = dot(d, d), b = dot(o, d), c = dot(o, o) - 1.0;
    float discriminant = b * b - a * c;
    if (discriminant < 0.0) discard;
    float root = sqrt(discriminant);
    float t = (-b - root) / a;
    if (t < 0.0) t = (-b + root) / a;  // the camera inside: the far side
    if (t < 0.0) discard;
    float3 local = o + t * d;  // on the unit sphere
    float3 worldNormal = normalize((local.x / scale.x) * tangent + (local.y / scale.y) * normal + (local.z / scale.z) * bitangent);
    float4 clip = mul(frame.viewProjection, float4(frame.cameraPosition.xyz + t * direction, 1.0));
    depth = saturate(clip.z / clip.w);
    // Rings alternate between two tints, so that their boundaries show.
    float3 albedo = (uint(p.shape.w) & 1u) ? float3(0.85, 0.75, 0.6) : float3(0.6, 0.75, 0.9);
    float lambert = max(dot(worldNormal, frame.directionToSun.xyz), 0.0);
    return float4(albedo / 3.14159265 * frame.sunIrradiance.rgb * (lambert + 0.15), 1.0);
}
