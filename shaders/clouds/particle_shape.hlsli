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

// The cloud medium's extinction coefficient at density 1 (1/m): Yusov's sample's, in the range
// of cumulus (0.01 to 0.1); all of it scattering.
static const float kCloudExtinction = 0.07;

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

// The pixel's view direction (world, unit), in a target of 1 / size `inverseSize` (the frame's,
// or the clouds' low-resolution target's).
float3 pixelDirection(float4 position, float2 inverseSize) {
    float2 ndc = float2(position.x * inverseSize.x * 2.0 - 1.0, 1.0 - position.y * inverseSize.y * 2.0);
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

// The same for the ray from `origin` (near and far then from it).
bool hitParticleFrom(CloudParticle p, float3 origin, float3 direction, out ParticleHit hit) {
    particleFrame(p.centre.xyz, hit.tangent, hit.normal, hit.bitangent);
    hit.scale = float3(p.centre.w, p.shape.x, p.centre.w);
    float3 toCamera = origin - p.centre.xyz;
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

bool hitParticle(CloudParticle p, float3 direction, out ParticleHit hit) { return hitParticleFrom(p, frame.cameraPosition.xyz, direction, hit); }

// The distance from the camera to the scene at this pixel (far away where nothing was drawn), the
// depth buffer of the target's size.
float sceneDistance(Texture2D<float> depthBuffer, float4 position, float2 inverseSize) {
    float depth = depthBuffer.Load(int3(position.xy, 0));
    if (depth <= 0.0) return 3.0e38;
    float2 ndc = float2(position.x * inverseSize.x * 2.0 - 1.0, 1.0 - position.y * inverseSize.y * 2.0);
    float4 world = mul(frame.inverseViewProjection, float4(ndc, depth, 1.0));
    return length(world.xyz / world.w - frame.cameraPosition.xyz);
}

#ifdef FIRMAMENT_OPTICAL_DEPTH_TABLE_HLSLI
// The particle's optical depth over `length` metres of its chord (Yusov 2014): the table's mean
// density along the whole chord, the particle's noise turned by its azimuth, times the length in
// front of the camera and the scene, the particle's density and the extinction.
float particleOpticalDepth(CloudParticle p, ParticleHit hit, float length, Texture3D<float> table, SamplerState linearWrap) {
    float4 u = opticalDepthCoordinates(hit.entry, hit.through);
    u.y += p.shape.z / (2.0 * kTablePi);
    return sampleOpticalDepth(table, linearWrap, u, field.tableSizes) * length * p.shape.y * kCloudExtinction;
}

// A pixel of a particle's quad: the particle, the view ray, its hit, the visible stretch
// [start, end] (m from the camera), its optical depth tau and opacity 1 - e^(-tau); false where
// the ray misses the particle, or the camera or the scene hides all of it.
struct ParticlePixel {
    CloudParticle particle;
    float3 direction;
    ParticleHit hit;
    float start;
    float end;
    float opticalDepth;
    float opacity;
};

bool particlePixel(ShapeVertex input, Texture2D<float> depthBuffer, float2 inverseSize, Texture3D<float> table, SamplerState linearWrap,
                   out ParticlePixel px) {
    px.particle = particles[input.slot];
    px.direction = pixelDirection(input.position, inverseSize);
    px.start = 0.0;
    px.end = 0.0;
    px.opticalDepth = 0.0;
    px.opacity = 0.0;
    if (!hitParticle(px.particle, px.direction, px.hit)) return false;
    px.start = max(px.hit.near, 0.0);
    px.end = min(px.hit.far, sceneDistance(depthBuffer, input.position, inverseSize));
    if (px.end <= px.start) return false;
    px.opticalDepth = particleOpticalDepth(px.particle, px.hit, px.end - px.start, table, linearWrap);
    px.opacity = 1.0 - exp(-px.opticalDepth);
    return true;
}
#endif

#endif
