// Orientation grid: a reference ground to read distances and the sun's direction from, under
// the terrain or alone. A flat ground plane (y = 0) with grid lines every 100 m, 1 km and
// 10 km, lit by the sun with a Lambert term, under a two-colour sky gradient with a sun disc.
// Not a physical model (Basic panel, "Orientation grid").
// GROUND_ONLY=1 (light scattering on): only the ground, now the Earth's sphere (so that it
// meets the spherical atmosphere, and curves away seen from orbit), beyond the terrain's reach
// when the terrain draws, lit by the sun's
// irradiance with a Lambert term and a flat ambient, and its depth, so that the atmosphere's
// pass draws the sky and adds aerial perspective. The terrain issue brings physical lighting.
#include "common/fullscreen_triangle.hlsli"
#include "common/shared_structures.hlsli"

cbuffer FrameBuffer : register(b0) {
    FrameConstants frame;
};

static const float kPi = 3.14159265;
static const float3 kZenithRadiance = float3(0.05, 0.10, 0.30);
static const float3 kHorizonRadiance = float3(0.35, 0.40, 0.50);
static const float3 kGroundAlbedo = float3(0.18, 0.20, 0.16);
static const float3 kLineAlbedo = float3(0.60, 0.60, 0.55);
static const float3 kSunRadiance = float3(40.0, 38.0, 34.0);
static const float kCosSunRadius = 0.99985;  // about 1 degree: a disc easy to see
static const float kHazeDistance = 60000.0;  // metres over which the grid fades into the horizon
static const float kAmbientFraction = 0.1;     // GROUND_ONLY: a crude stand-in for the sky's light

#ifndef GROUND_ONLY
#define GROUND_ONLY 0
#endif

// Coverage of grid lines of the given spacing and width at `position` (metres), filtered by
// the pixel's footprint so distant lines fade instead of flickering.
float gridLines(float2 position, float spacing, float width) {
    float2 cell = position / spacing;
    float2 footprint = max(fwidth(cell), 1e-5);
    float2 distanceToLine = abs(frac(cell + 0.5) - 0.5);
    float2 coverage = 1.0 - saturate((distanceToLine - width / spacing * 0.5) / footprint);
    float fade = saturate(1.0 - max(footprint.x, footprint.y) * 2.0);
    return max(coverage.x, coverage.y) * fade;
}

float3 skyRadiance(float3 direction) {
    float3 sky = lerp(kHorizonRadiance, kZenithRadiance, sqrt(saturate(direction.y)));
    float3 sun = dot(direction, frame.directionToSun.xyz) > kCosSunRadius ? kSunRadiance : 0.0;
    return sky * saturate(frame.directionToSun.y * 4.0 + 0.25) + sun;
}

FullscreenVertex vs_main(uint vertexId : SV_VertexID) {
    return fullscreenTriangle(vertexId);
}

float3 groundAlbedo(float2 ground) {
    float lines = max(max(gridLines(ground, 100.0, 2.0), gridLines(ground, 1000.0, 12.0)), gridLines(ground, 10000.0, 120.0));
    return lerp(kGroundAlbedo, kLineAlbedo, lines);
}

float3 viewDirection(FullscreenVertex input) {
    float2 ndc = float2(input.uv.x * 2.0 - 1.0, 1.0 - input.uv.y * 2.0);
    float4 farPoint = mul(frame.clipToDirection, float4(ndc, 1.0, 1.0));
    return normalize(farPoint.xyz / farPoint.w);
}

#if GROUND_ONLY
float4 ps_main(FullscreenVertex input, out float depth : SV_Depth) : SV_Target {
    float3 direction = viewDirection(input);
    // The Earth's sphere about (0, -R, 0): |P + t d|^2 = R^2 with P from the centre. In float,
    // |P|^2 - R^2 and -b - sqrt(b^2 - c) both lose metres to cancellation (|P| is 6.4e6 m), so
    // c is expanded from the camera's coordinates and the near root taken as c / (-b + sqrt).
    float radius = frame.planet.x;
    float3 camera = frame.cameraPosition.xyz;
    float b = dot(camera, direction) + radius * direction.y;
    float c = dot(camera.xz, camera.xz) + camera.y * (2.0 * radius + camera.y);
    float discriminant = b * b - c;
    if (discriminant < 0.0 || b >= 0.0) discard;
    float distance = c / (-b + sqrt(discriminant));
    if (distance <= 0.0) discard;
    float3 ground = frame.cameraPosition.xyz + direction * distance;
    // Under the terrain the grid would fight it in depth (the terrain's plains lie within
    // metres of the sphere): the grid's ground lies outside the terrain's square.
    float2 fromTerrain = abs(ground.xz - frame.planet.zw);
    if (max(fromTerrain.x, fromTerrain.y) < frame.planet.y) discard;
    float4 clip = mul(frame.viewProjection, float4(ground, 1.0));
    depth = saturate(clip.z / clip.w);
    if (depth <= 0.0) discard;  // beyond the far plane (reversed Z): the sky pass sees the ground there
    float3 normal = normalize(ground + float3(0.0, radius, 0.0));
    float cosSun = dot(normal, frame.directionToSun.xyz);
    float light = saturate(cosSun) + kAmbientFraction * saturate(cosSun * 4.0 + 0.25);
    return float4(groundAlbedo(ground.xz) / kPi * frame.sunIrradiance.rgb * light, 1.0);
}
#else
float4 ps_main(FullscreenVertex input) : SV_Target {
    float3 direction = viewDirection(input);
    float3 radiance = skyRadiance(direction);

    if (direction.y < 0.0) {
        float distance = frame.cameraPosition.y / -direction.y;
        float2 ground = frame.cameraPosition.xz + direction.xz * distance;
        float3 albedo = groundAlbedo(ground);
        float sunLight = saturate(frame.directionToSun.y);
        float3 lit = albedo * (sunLight * 3.0 + 0.15);
        float haze = 1.0 - exp(-distance / kHazeDistance);
        radiance = lerp(lit, skyRadiance(float3(direction.x, 0.0, direction.z)) * 0.8, haze);
    }
    return float4(radiance, 1.0);
}
#endif
