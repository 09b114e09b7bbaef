// Yusov 2013's atmosphere at render time, without light shafts ("Enable light scattering" on,
// "Enable light shafts" off), as two passes over the frame:
//  - ps_sky, where nothing was drawn (depth 0, the far plane): the sky, L(C, v) times the sun's
//    irradiance, and the sun's disc attenuated by the atmosphere where the ground does not hide it;
//  - ps_aerial_perspective, over geometry at P: its radiance times T(C -> P), plus the light
//    scattered in between, L(C, v) - T(C -> P) L(P, v) (eq. 8). The light shafts replace it.
// Single scattering comes from the table, from numerical integration along the ray (the
// reference the table is measured against), or not at all; the higher orders from the
// high-order table. Without light shafts nothing is occluded, so Occluded differs from
// Unoccluded only with single scattering from the table: then the multiple scattering table
// gives all orders in one look-up (docs/atmosphere.md, "Render modes").
#include "common/fullscreen_triangle.hlsli"
#include "atmosphere/yusov/aerial_perspective.hlsli"

cbuffer FrameBuffer : register(b0) {
    FrameConstants frame;
};
cbuffer AtmosphereBuffer : register(b1) {
    AtmosphereConstants atmosphere;
};
cbuffer YusovPassBuffer : register(b2) {
    YusovPassConstants scattering;
};

Texture2D<float4> sceneRadiance : register(t0);  // the HDR frame before this pass (ps_aerial_perspective)
Texture2D<float> sceneDepth : register(t1);
Texture2D<float4> netDensityLut : register(t2);
Texture3D<float4> singleScatteringLut : register(t3);
Texture3D<float4> highOrderScatteringLut : register(t4);
Texture3D<float4> multipleScatteringLut : register(t5);
SamplerState linearClamp : register(s0);

static const uint kSingleScatteringNone = 0;
static const uint kSingleScatteringIntegration = 1;
static const uint kMultipleScatteringNone = 0;
static const uint kSingleScatteringTable = 2;
static const uint kMultipleScatteringOccluded = 1;

FullscreenVertex vs_main(uint vertexId : SV_VertexID) {
    return fullscreenTriangle(vertexId);
}

// The light a table holds between start and start + length viewDir: the whole ray's, or eq. 8.
float3 tableBetween(Texture3D<float4> lut, float3 start, float3 viewDir, float3 sunDir, float rayLength, bool hitsGround, bool toEnd) {
    int side = hitsGround ? kBelowHorizon : kAboveHorizon;
    float3 fromStart = lookUpScattering(atmosphere, lut, linearClamp, start, viewDir, sunDir, side);
    if (toEnd) return fromStart;
    float3 end = start + viewDir * rayLength;
    float3 fromEnd = lookUpScattering(atmosphere, lut, linearClamp, end, viewDir, sunDir, side);
    return max(fromStart - transmittanceBetween(atmosphere, netDensityLut, linearClamp, start, end, viewDir) * fromEnd, 0.0);
}

// In-scattered light per unit irradiance along start -> start + length viewDir: single
// scattering as its mode says, and the higher orders as theirs.
float3 inscattering(float3 start, float3 viewDir, float3 sunDir, float rayLength, bool hitsGround, bool toEnd) {
    if (scattering.mode.z == kMultipleScatteringOccluded && scattering.mode.x == kSingleScatteringTable)
        return tableBetween(multipleScatteringLut, start, viewDir, sunDir, rayLength, hitsGround, toEnd);
    float3 light = 0.0;
    if (scattering.mode.x == kSingleScatteringIntegration)
        light = integrateSingleScattering(atmosphere, netDensityLut, linearClamp, start, viewDir, sunDir, rayLength, (int)scattering.mode.y);
    else if (scattering.mode.x == kSingleScatteringTable)
        light = tableBetween(singleScatteringLut, start, viewDir, sunDir, rayLength, hitsGround, toEnd);
    if (scattering.mode.z != kMultipleScatteringNone)
        light += tableBetween(highOrderScatteringLut, start, viewDir, sunDir, rayLength, hitsGround, toEnd);
    return light;
}

// The pixel's radiance once the atmosphere is applied; `depth` is its scene depth, `radiance`
// what the scene drew there (read over geometry only).
float3 shade(FullscreenVertex input, float depth) {
    int2 pixel = int2(input.position.xy);
    float3 radiance = depth > 0.0 ? sceneRadiance.Load(int3(pixel, 0)).rgb : 0.0;
    float2 ndc = float2(input.uv.x * 2.0 - 1.0, 1.0 - input.uv.y * 2.0);
    float4 farPoint = mul(frame.clipToDirection, float4(ndc, 1.0, 1.0));
    float3 viewDir = normalize(farPoint.xyz / farPoint.w);
    float3 sunDir = frame.directionToSun.xyz;
    float3 earthCentre = float3(0.0, -atmosphere.earth.x, 0.0);
    float3 start = frame.cameraPosition.xyz - earthCentre;

    float offset;
    bool inAtmosphere = clipRayToAtmosphere(atmosphere, start, viewDir, offset);
    bool geometry = depth > 0.0;  // reversed Z: 0 is the far plane, where nothing was drawn
    float geometryDistance = 0.0;
    if (geometry) {
        float4 world = mul(frame.inverseViewProjection, float4(ndc, depth, 1.0));
        geometryDistance = length(world.xyz / world.w - frame.cameraPosition.xyz) - offset;
    }
    if (!inAtmosphere || (geometry && geometryDistance <= 0.0)) {
        // Outside the atmosphere: geometry and the sun as they are, space is black.
        bool sunHere = !geometry && dot(viewDir, sunDir) > scattering.sun.x && !rayHitsGround(atmosphere, frame.cameraPosition.xyz - earthCentre, viewDir);
        return geometry ? radiance : (sunHere ? frame.sunIrradiance.rgb * scattering.sun.y : 0.0);
    }

    bool hitsGround = rayHitsGround(atmosphere, start, viewDir);
    float toEnd = rayLengthInAtmosphere(atmosphere, start, viewDir, hitsGround);
    if (geometry) {
        // Geometry on the ground lies where the ray meets the Earth: a comparison would be
        // decided by rounding pixel by pixel, so the distance is clamped to the ray's end.
        float distance = min(geometryDistance, toEnd);
        float3 end = start + viewDir * distance;
        float3 transmittance = transmittanceBetween(atmosphere, netDensityLut, linearClamp, start, end, viewDir);
        float3 scattered = inscattering(start, viewDir, sunDir, distance, hitsGround, false);
        return radiance * transmittance + frame.sunIrradiance.rgb * scattered;
    }
    float3 sky = frame.sunIrradiance.rgb * inscattering(start, viewDir, sunDir, toEnd, hitsGround, true);
    if (!hitsGround && dot(viewDir, sunDir) > scattering.sun.x) {
        float h = length(start) - atmosphere.earth.x;
        sky += frame.sunIrradiance.rgb * scattering.sun.y * sunTransmittance(atmosphere, netDensityLut, linearClamp, h, dot(normalize(start), viewDir));
    }
    return sky;
}

float4 ps_sky(FullscreenVertex input) : SV_Target {
    float depth = sceneDepth.Load(int3(int2(input.position.xy), 0));
    if (depth > 0.0) discard;  // reversed Z: geometry, the other pass's
    return float4(shade(input, depth), 1.0);
}

float4 ps_aerial_perspective(FullscreenVertex input) : SV_Target {
    float depth = sceneDepth.Load(int3(int2(input.position.xy), 0));
    if (depth <= 0.0) discard;  // nothing drawn: the sky pass's
    return float4(shade(input, depth), 1.0);
}
