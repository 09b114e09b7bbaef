#ifndef FIRMAMENT_PARTICLE_SHAPE_HLSLI
#define FIRMAMENT_PARTICLE_SHAPE_HLSLI
// A particle on the screen: the camera-facing quad that covers its ellipsoid, drawn instanced in
// back-to-front order (DrawInstancedIndirect), and the view ray's intersection with the
// ellipsoid in the particle's unit-sphere space, whose y axis is the planet's normal.
#include "clouds/cloud_field.hlsli"

StructuredBuffer<uint2> sortedKeys : register(t0);  // y: the particle's slot
StructuredBuffer<CloudParticle> particles : register(t1);

struct ShapeVertex {
    float4 position : SV_Position;
    nointerpolation uint slot : PARTICLE;
};

// The ellipsoid's axes: two tangents and the planet's normal through its centre.
void particleFrame(float3 centre, out float3 tangent, out float3 normal, out float3 bitangent) {
    normal = normalize(centre + float3(0.0, frame.planet.x, 0.0));
    tangent = normalize(cross(normal, float3(0.0, 0.0, 1.0)));
    bitangent = cross(tangent, normal);
}

ShapeVertex shapeVertex(uint vertexId, uint instance) {
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

// The pixel's view direction (world, unit).
float3 pixelDirection(float4 position) {
    float2 ndc = float2(position.x * frame.screen.z * 2.0 - 1.0, 1.0 - position.y * frame.screen.w * 2.0);
    float4 farPoint = mul(frame.clipToDirection, float4(ndc, 1.0, 1.0));
    return normalize(farPoint.xyz / farPoint.w);
}

// The view ray against the particle's ellipsoid. In its unit-sphere space (x tangent, y normal,
// z bitangent, each divided by the radius along it) the ray is o + t d, t the world distance
// along `direction`; false when it misses. `entry` and `through` are where and along what the
// whole line enters the unit sphere.
struct ParticleHit {
    float near, far;  // world distances from the camera where the line enters and leaves (near may be < 0)
    float3 entry;     // on the unit sphere
    float3 through;   // unit, in unit-sphere space
    float3 scale;     // the radii along x, y, z
    float3 tangent, normal, bitangent;
};

bool hitParticle(CloudParticle p, float3 direction, out ParticleHit hit) {
    particleFrame(p.centre.xyz, hit.tangent, hit.normal, hit.bitangent);
    hit.scale = float3(p.centre.w, p.shape.x, p.centre.w);
    float3 toCamera = frame.cameraPosition.xyz - p.centre.xyz;
    float3 o = float3(dot(toCamera, hit.tangent), dot(toCamera, hit.normal), dot(toCamera, hit.bitangent)) / hit.scale;
    float3 d = float3(dot(direction, hit.tangent), dot(direction, hit.normal), dot(direction, hit.bitangent)) / hit.scale;
    float a = dot(d, d), b = dot(o, d), c = dot(o, o) - 1.0;
    float discriminant = b * b - a * c;
    hit.near = 0.0;
    hit.far = 0.0;
    hit.entry = 0.0;
    hit.through = 0.0;
    if (discriminant < 0.0) return false;
    float root = sqrt(discriminant);
    hit.near = (-b - root) / a;
    hit.far = (-b + root) / a;
    hit.entry = normalize(o + hit.near * d);
    hit.through = normalize(d);
    return hit.far > 0.0;
}

#endif
