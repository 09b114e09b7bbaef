#ifndef FIRMAMENT_YUSOV_VIEW_RAY_HLSLI
#define FIRMAMENT_YUSOV_VIEW_RAY_HLSLI
// A view ray's part inside the atmosphere, and the light scattered into stretches of it from
// Yusov 2013's tables or by integration: what the atmosphere's own passes draw for the whole
// ray (scatteringAlongRay) and what the light shafts add up over its lit parts
// (lightshafts/ray_march.hlsli). Render modes: docs/atmosphere.md, "Render modes".
//
// The includer declares: cbuffer `atmosphere` (AtmosphereConstants); Texture2D<float4>
// netDensityLut; Texture3D<float4> singleScatteringLut, highOrderScatteringLut,
// multipleScatteringLut; SamplerState linearClamp.
#include "atmosphere/yusov/aerial_perspective.hlsli"

// The render modes' values (AtmosphereSettings.h: SingleScatteringMode, MultipleScatteringMode).
static const uint kSingleScatteringNone = 0;
static const uint kSingleScatteringIntegration = 1;
static const uint kSingleScatteringTable = 2;
static const uint kMultipleScatteringNone = 0;
static const uint kMultipleScatteringOccluded = 1;
static const uint kMultipleScatteringUnoccluded = 2;

// Which table eq. 8 reads.
static const uint kNoTable = 0;
static const uint kSingleTable = 1;
static const uint kHighOrderTable = 2;
static const uint kMultipleTable = 3;

// Distances s along the ray count from `start`.
struct ViewRay {
    float3 camera;        // the camera, in world space
    float3 start;         // where the ray enters the atmosphere (the camera inside it), from the Earth's centre
    float3 viewDir;
    float offset;         // from the camera to start
    float length;         // from start to the ray's end: geometry, the ground or the top
    bool hitsGround;      // the side of the horizon every table look-up uses
    bool endsAtBoundary;  // no geometry: nothing is scattered beyond the end (L there is 0)
};

float3 lookUpTable(uint table, float3 position, float3 viewDir, float3 sunDir, int side) {
    if (table == kSingleTable) return lookUpSpeciesScattering(atmosphere, singleScatteringLut, linearClamp, position, viewDir, sunDir, side);
    if (table == kHighOrderTable) return lookUpScattering(atmosphere, highOrderScatteringLut, linearClamp, position, viewDir, sunDir, side);
    return lookUpSpeciesScattering(atmosphere, multipleScatteringLut, linearClamp, position, viewDir, sunDir, side);
}

float3 transmittanceTo(ViewRay ray, float s) {
    return s > 0.0 ? transmittanceBetween(atmosphere, netDensityLut, linearClamp, ray.start, ray.start + ray.viewDir * s, ray.viewDir) : 1.0;
}

// Eq. 8 over [s0, s1]: T(start -> s0) L(s0, v) - T(start -> s1) L(s1, v), from one table.
float3 tableSection(uint table, ViewRay ray, float3 sunDir, float s0, float s1) {
    if (table == kNoTable || s1 <= s0) return 0.0;
    int side = ray.hitsGround ? kBelowHorizon : kAboveHorizon;
    float3 light = transmittanceTo(ray, s0) * lookUpTable(table, ray.start + ray.viewDir * s0, ray.viewDir, sunDir, side);
    if (!(ray.endsAtBoundary && s1 >= ray.length))
        light -= transmittanceTo(ray, s1) * lookUpTable(table, ray.start + ray.viewDir * s1, ray.viewDir, sunDir, side);
    return max(light, 0.0);
}

// Single scattering over [s0, s1], by the spaced quadrature, seen from the start.
float3 integratedSection(ViewRay ray, float3 sunDir, float s0, float s1, int steps) {
    if (s1 <= s0) return 0.0;
    float3 from = ray.start + ray.viewDir * s0;
    return transmittanceTo(ray, s0) *
           integrateSingleScattering(atmosphere, netDensityLut, linearClamp, from, ray.viewDir, sunDir, s1 - s0, steps);
}

// The table eq. 8 reads over the lit parts of a ray, by the render modes: the multiple
// scattering table (all orders) with single scattering from the table and occluded higher
// orders, the single scattering table with unoccluded or no higher orders, the high-order
// table with single scattering not from the table and occluded higher orders.
uint litTable(uint single, uint multiple) {
    if (single == kSingleScatteringTable) return multiple == kMultipleScatteringOccluded ? kMultipleTable : kSingleTable;
    return multiple == kMultipleScatteringOccluded ? kHighOrderTable : kNoTable;
}

// The light scattered into the whole ray, per unit sun irradiance, with nothing occluded.
float3 scatteringAlongRay(ViewRay ray, float3 sunDir, uint single, uint multiple, int steps) {
    float3 light = 0.0;
    if (single == kSingleScatteringIntegration) light += integratedSection(ray, sunDir, 0.0, ray.length, steps);
    light += tableSection(litTable(single, multiple), ray, sunDir, 0.0, ray.length);
    if (multiple == kMultipleScatteringUnoccluded) light += tableSection(kHighOrderTable, ray, sunDir, 0.0, ray.length);
    return light;
}

#endif
