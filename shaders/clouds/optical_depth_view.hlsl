// Show particles: optical depth. Each particle white, with the transparency exp(-tau) of its
// optical depth along the view ray from the particle's table (Yusov 2014, "Pre-computing optical
// depth"), blended back to front over the scene and cut by the scene's depth: the second step of
// the paper's algorithm overview, before any lighting (docs/clouds.md).
#include "clouds/optical_depth_table.hlsli"
#include "clouds/particle_shape.hlsli"

Texture3D<float> opticalDepthTable : register(t2);
Texture2D<float> sceneDepth : register(t3);
SamplerState linearWrapSampler : register(s0);

// The cloud medium's extinction coefficient at density 1 (1/m): Yusov's sample's, in the range
// of cumulus (0.01 to 0.1).
static const float kCloudExtinction = 0.07;

ShapeVertex vs_main(uint vertexId : SV_VertexID, uint instance : SV_InstanceID) { return shapeVertex(vertexId, instance); }

// The distance from the camera to the scene along `direction` at this pixel (far away for the sky).
float sceneDistance(float4 position, float3 direction) {
    float depth = sceneDepth.Load(int3(position.xy, 0));
    if (depth <= 0.0) return 3.0e38;
    float2 ndc = float2(position.x * frame.screen.z * 2.0 - 1.0, 1.0 - position.y * frame.screen.w * 2.0);
    float4 world = mul(frame.inverseViewProjection, float4(ndc, depth, 1.0));
    return length(world.xyz / world.w - frame.cameraPosition.xyz);
}

float4 ps_main(ShapeVertex input) : SV_Target {
    CloudParticle p = particles[input.slot];
    float3 direction = pixelDirection(input.position);
    ParticleHit hit;
    if (!hitParticle(p, direction, hit)) discard;
    float start = max(hit.near, 0.0), end = min(hit.far, sceneDistance(input.position, direction));
    if (end <= start) discard;
    // The table's mean density along the whole chord, the particle's noise turned by its azimuth;
    // the part in front of the camera and the scene takes its share of the length.
    float4 u = opticalDepthCoordinates(hit.entry, hit.through);
    u.y += p.shape.z / (2.0 * kTablePi);
    float mean = sampleOpticalDepth(opticalDepthTable, linearWrapSampler, u, field.tableSizes);
    float tau = mean * (end - start) * p.shape.y * kCloudExtinction;
    float opacity = 1.0 - exp(-tau);
    float3 white = frame.sunIrradiance.rgb * (0.8 / 3.14159265);
    return float4(white * opacity, opacity);
}
