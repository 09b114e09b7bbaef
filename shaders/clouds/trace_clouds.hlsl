// The clouds' path-traced reference over the frame (Reference (path traced); docs/clouds.md,
// "Path-traced reference"), through the atmosphere model drawn (CLOUD_ATMOSPHERE 1: Yusov 2013,
// 2: Bruneton and Neyret 2008, 3: Hillaire 2020; clouds/cloud_atmosphere.hlsli):
// a thread per pixel traced this pass adds reference.paths.y paths (clouds/reference_paths.hlsli) from the camera
// through the pixel's centre to its accumulation: the light the paths gathered (per the sun's
// irradiance above the atmosphere, times it) and how many reached the scene behind the clouds
// (clouds/reference_composite.hlsl blends their mean over the frame).
// The light at the clouds: the sun's irradiance times the atmosphere's transmittance to it; the
// sky's radiance along each ray that leaves, from the atmosphere's tables (the light scattered
// along it to the top of the atmosphere or the ground); the air between the camera and the first
// collision, and between a cloud and the ground, by its transmittance and in-scattering; the
// ground a Lambertian sphere at altitude 0 of albedo reference.ground.yzw.
#include "atmosphere/atmosphere_structures.hlsli"
#include "clouds/cloud_structures.hlsli"

cbuffer AtmosphereBuffer : register(b2) { AtmosphereConstants atmosphere; };
cbuffer CloudReferenceBuffer : register(b3) { CloudReferenceConstants reference; };
Texture2D<float> sceneDepth : register(t3);  // the frame's
SamplerState linearClamp : register(s1);

#include "clouds/reference_medium.hlsli"
#include "clouds/cloud_atmosphere.hlsli"

float3 sunAt(float3 x) {
    float3 sunLight, skyLight;
    lightAtPoint(x, sunLight, skyLight);
    return sunLight;
}

// The air; at kFar, to the top of the atmosphere (the sky's light along the ray).
void segment(float3 x, float3 d, float distance, out float3 transmittance, out float3 light) {
    atmosphereSegment(x, d, distance, reference.modes, transmittance, light);
}

// The ground: the planet's surface sphere.
float groundDistance(float3 x, float3 d) {
    float2 roots = sphereRoots(x, d, frame.planet.x);
    return roots.y >= roots.x && roots.x > 0.0 ? roots.x : 3.0e38;
}
float3 groundAlbedo(float3 x) { return reference.ground.yzw; }
float3 groundNormal(float3 x) { return normalize(x + float3(0.0, frame.planet.x, 0.0)); }

#include "clouds/reference_paths.hlsli"

RWTexture2D<float4> accumulation : register(u0);

// A thread per pixel of this pass's phase: one pixel of every options.w x options.w block, the
// blocks' pixels taken in row order pass after pass (paths.x counts the passes before this one).
[numthreads(8, 8, 1)]
void main(uint3 id : SV_DispatchThreadID) {
    uint stride = reference.options.w;
    uint phase = reference.paths.x % (stride * stride);
    uint2 pixel = id.xy * stride + uint2(phase % stride, phase / stride);
    if (float(pixel.x) >= reference.target.x || float(pixel.y) >= reference.target.y) return;
    float4 position = float4(float2(pixel) + 0.5, 0.0, 1.0);
    float3 direction = pixelDirection(position, reference.target.zw);
    float tScene = sceneDistance(sceneDepth, position, reference.target.zw);
    uint state = hash32(pixel.x ^ hash32(pixel.y ^ hash32(reference.paths.z)));
    float4 sum = 0.0;
    for (uint k = 0; k < reference.paths.y; ++k) {
        PathSample s = tracePath(frame.cameraPosition.xyz, direction, tScene, true, reference.options.z, state);
        sum += float4(s.light * frame.sunIrradiance.rgb, s.escaped);
    }
    // Its pass of an earlier round left the pixel's sums.
    if (reference.paths.x >= stride * stride) sum += accumulation[pixel];
    accumulation[pixel] = sum;
}
