#ifndef FIRMAMENT_LIGHTSHAFTS_RAY_MARCH_HLSLI
#define FIRMAMENT_LIGHTSHAFTS_RAY_MARCH_HLSLI
// The light scattered along a view ray where the sun reaches it (Yusov 2013, "Light shafts
// calculation using scattering look-up table"; Yusov's GPU Pro 5 chapter). The ray is marched
// through the shadow cascades one shadow-map texel at a time; the sun's visibility at each step
// gives, by the render modes (docs/atmosphere.md, "Render modes"):
//  - Integration: single scattering summed over the steps, each weighted by its visibility;
//  - a table (LUT, or the higher orders when occluded): the total lit length D_lit and the
//    distance D_start to the first lit point, and eq. 8 over [D_start, D_start + D_lit]
//    (two look-ups on one side of the horizon);
//  - unoccluded higher orders: eq. 8 over the whole ray, shadows or not.
// The march starts at the camera: the first marched cascade ("First cascade to ray march") is
// fitted around the camera's place as well as its own slice of the frustum
// (src/shadows/CascadeSplits.h), so it covers the near stretch the finer cascades would have,
// and a caster nearer than its split still shadows the haze. The stretch beyond the last cascade
// (or beyond the shafts' end, 300 km) counts as lit: Integration integrates it with the spaced
// quadrature of single_scattering.hlsli, the tables take eq. 8 over it.
//
// With the epipolar sampling's 1D min/max trees (FIRMAMENT_MINMAX_TREES, the march of the
// epipolar samples), the steps a tree proves uniformly lit or shadowed are taken a node at a time
// without sampling the map (lightshafts/minmax_trees.hlsli); the result is the same.
//
// With FIRMAMENT_CLOUD_SHADOWS ("Shafts from clouds: transparency map", Yusov 2014), each step's
// visibility is multiplied by the clouds' transmittance at the step's middle
// (shadows/cloud_shadow.hlsli): the steps a tree proves lit are then taken one at a time for it,
// so the epipolar march and the brute force still agree.
//
// The includer declares: cbuffers `atmosphere` (AtmosphereConstants), `lightShafts`
// (LightShaftConstants) and `shadows` (ShadowConstants); Texture2D<float4> netDensityLut;
// Texture3D<float4> singleScatteringLut, highOrderScatteringLut, multipleScatteringLut;
// Texture2D<float> shadowMap; SamplerState linearClamp; SamplerComparisonState shadowComparison;
// with the trees, what minmax_trees.hlsli needs; with the clouds, the cbuffer `cloudShadow`
// (CloudShadowConstants) and Texture2D<float4> cloudShadowMap.
#include "atmosphere/yusov/view_ray.hlsli"
#include "lightshafts/lightshaft_structures.hlsli"
#include "shadows/cascade_sampling.hlsli"
#ifdef FIRMAMENT_MINMAX_TREES
#include "lightshafts/minmax_trees.hlsli"
#endif
#ifdef FIRMAMENT_CLOUD_SHADOWS
#include "shadows/cloud_shadow.hlsli"
#endif

// Whether the clouds shadow the march this frame.
bool cloudShadowsOn() {
#ifdef FIRMAMENT_CLOUD_SHADOWS
    return cloudShadow.up.w != 0.0;
#else
    return false;
#endif
}

// The share of the sun's light the clouds let reach `position` (1 without them).
float cloudTransmittanceAt(float3 position) {
#ifdef FIRMAMENT_CLOUD_SHADOWS
    return cloudTransmittance(position);
#else
    return 1.0;
#endif
}

// What the march through the cascades found.
struct ShadowMarch {
    float begin, end;        // the marched stretch [begin, end] of the ray (equal when nothing was marched)
    float litLength;         // D_lit: the lit length within it (visibility-weighted)
    float firstLit;          // D_start: where the first lit step begins (end when none is lit)
    float3 singleScattering; // Integration: single scattering over the stretch, lit steps only
};

// What the march through one cascade found, over the cascade's part of the stretch.
struct CascadeMarch {
    float litLength;
    float firstLit;          // where its first lit step begins; -1 when none is lit
    float3 singleScattering;
};

// The sun's visibility at a point of cascade c's tile (u, v, depth): 1 outside the tile.
float cascadeVisibility(uint c, float3 uvz) {
    if (any(uvz.xy < 0.0) || any(uvz.xy > 1.0) || uvz.z < 0.0 || uvz.z > 1.0) return 1.0;
    return shadowMap.SampleCmpLevelZero(shadowComparison, atlasCoordinates(c, uvz.xy), uvz.z - shadows.map.z);
}

// Where cascade c's part of the march begins, in view depth: its split, or the camera for the
// first marched cascade, whose map holds the camera's place.
float marchedCascadeStart(uint c) {
    return c == lightShafts.mode.w ? 0.0 : cascadeSplit(c);
}

// The stretch the march covers: from the camera (or where the ray enters the atmosphere) to the
// last cascade's view depth, seen along the ray (view depth z lies at z / (v . forward)), up to
// the shafts' end; nothing marched yet.
ShadowMarch marchedStretch(ViewRay ray) {
    ShadowMarch m;
    m.begin = 0.0;
    m.end = 0.0;
    m.litLength = 0.0;
    m.firstLit = 0.0;
    m.singleScattering = 0.0;
    uint count = shadows.mode.x;
    uint first = lightShafts.mode.w;
    float cosForward = dot(ray.viewDir, shadows.cameraForward.xyz);
    if (count == 0 || first >= count || cosForward <= 1e-4) return m;
    float reach = min(lightShafts.march.x, cascadeSplit(count) / cosForward) - ray.offset;
    m.begin = clamp(marchedCascadeStart(first) / cosForward - ray.offset, 0.0, ray.length);
    m.end = clamp(reach, m.begin, ray.length);
    m.firstLit = m.end;
    return m;
}

// Marches cascade c's part of the stretch [begin, end] in steps of one texel of that cascade,
// at most lightShafts.march.y; the visibility is taken at each step's middle. With `integrate`,
// single scattering is summed too (midpoint rule, the optical depth from the start carried
// along from the cascade's first step). `slice`: the epipolar slice the ray lies in, whose
// trees the march walks (with FIRMAMENT_MINMAX_TREES).
CascadeMarch marchCascade(ViewRay ray, float3 sunDir, bool integrate, uint slice, uint c, float begin, float end) {
    CascadeMarch cm;
    cm.litLength = 0.0;
    cm.firstLit = -1.0;
    cm.singleScattering = 0.0;
    float cosForward = dot(ray.viewDir, shadows.cameraForward.xyz);
    float s0 = max(marchedCascadeStart(c) / cosForward - ray.offset, begin);
    float s1 = min(cascadeSplit(c + 1) / cosForward - ray.offset, end);
    if (s1 <= s0 || cosForward <= 1e-4) return cm;
    float3 uvz0 = shadowMapCoordinates(c, ray.camera + ray.viewDir * (ray.offset + s0));
    float3 uvz1 = shadowMapCoordinates(c, ray.camera + ray.viewDir * (ray.offset + s1));
    float texels = length(uvz1.xy - uvz0.xy) * shadows.map.x;
    uint steps = (uint)clamp(ceil(texels), integrate ? 8.0 : 1.0, lightShafts.march.y);
    float ds = (s1 - s0) / steps;
    float cosTheta = dot(ray.viewDir, sunDir);
    float3 netDensity = integrate ? netDensityBetween(atmosphere, netDensityLut, linearClamp, ray.start, ray.start + ray.viewDir * s0, ray.viewDir)
                                  : 0.0;
#ifdef FIRMAMENT_MINMAX_TREES
    TreeWalk walk = beginTreeWalk(c, slice, uvz0, uvz1, steps);
#endif
    bool clouds = cloudShadowsOn();
    bool perStep = integrate || clouds;
    [loop] for (uint i = 0; i < steps;) {
        // The visibility of step i, and of the steps after it that share it (`run` in all).
        uint run = 1;
        float visibility = -1.0;
#ifdef FIRMAMENT_MINMAX_TREES
        visibility = walkTree(walk, i, steps, run);
#endif
        if (visibility < 0.0) visibility = cascadeVisibility(c, lerp(uvz0, uvz1, (i + 0.5) / steps));
        if (!perStep) {
            if (cm.firstLit < 0.0 && visibility > 0.0) cm.firstLit = s0 + i * ds;
            cm.litLength += visibility * ds * run;
        } else {
            // Each step of the run on its own: its clouds, and with Integration its scattering.
            [loop] for (uint j = i; j < i + run; ++j) {
                float t = (j + 0.5) / steps;
                float3 position = ray.start + ray.viewDir * (s0 + t * (s1 - s0));
                float lit = visibility;
                if (clouds && lit > 0.0) lit *= cloudTransmittanceAt(ray.camera + ray.viewDir * (ray.offset + s0 + t * (s1 - s0)));
                if (cm.firstLit < 0.0 && lit > 0.0) cm.firstLit = s0 + j * ds;
                cm.litLength += lit * ds;
                if (integrate) {
                    float radius = length(position);
                    float h = radius - atmosphere.earth.x;
                    float3 density = particleDensity(atmosphere, h);
                    netDensity += density * (0.5 * ds);
                    cm.singleScattering += scatteringCoefficient(atmosphere, density, cosTheta) * exp(-opticalDepth(atmosphere, netDensity)) *
                                           sunTransmittance(atmosphere, netDensityLut, linearClamp, h, dot(position / radius, sunDir)) *
                                           (lit * ds);
                    netDensity += density * (0.5 * ds);
                }
            }
        }
        i += run;
    }
    return cm;
}

// Adds cascade's march to the whole, the cascades taken in order from the camera.
void addCascade(inout ShadowMarch m, CascadeMarch cm) {
    if (m.firstLit >= m.end && cm.firstLit >= 0.0) m.firstLit = cm.firstLit;
    m.litLength += cm.litLength;
    m.singleScattering += cm.singleScattering;
}

// Marches the ray through the cascades from the first to march to the last, or to the shafts'
// end, in one pass ("Cascade processing mode": single pass).
ShadowMarch marchShadows(ViewRay ray, float3 sunDir, bool integrate, uint slice) {
    ShadowMarch m = marchedStretch(ray);
    if (m.end <= m.begin) return m;
    [loop] for (uint c = lightShafts.mode.w; c < shadows.mode.x; ++c) addCascade(m, marchCascade(ray, sunDir, integrate, slice, c, m.begin, m.end));
    return m;
}

// The light scattered into the ray where the sun reaches, per unit sun irradiance, from what
// the march found.
float3 inscatteringFromMarch(ViewRay ray, float3 sunDir, ShadowMarch m) {
    uint single = lightShafts.mode.x, multiple = lightShafts.mode.z;
    int steps = (int)lightShafts.mode.y;
    float3 light = 0.0;
    if (single == kSingleScatteringIntegration)
        light += integratedSection(ray, sunDir, 0.0, m.begin, steps) + m.singleScattering +
                 integratedSection(ray, sunDir, m.end, ray.length, steps);
    uint table = litTable(single, multiple);
    light += tableSection(table, ray, sunDir, 0.0, m.begin) + tableSection(table, ray, sunDir, m.firstLit, m.firstLit + m.litLength) +
             tableSection(table, ray, sunDir, m.end, ray.length);
    if (multiple == kMultipleScatteringUnoccluded) light += tableSection(kHighOrderTable, ray, sunDir, 0.0, ray.length);
    return light;
}

// The light scattered into the ray where the sun reaches, per unit sun irradiance; `slice` as
// marchShadows takes it.
float3 shadowedInscatteringInSlice(ViewRay ray, float3 sunDir, uint slice) {
    bool integrate = lightShafts.mode.x == kSingleScatteringIntegration;
    return inscatteringFromMarch(ray, sunDir, marchShadows(ray, sunDir, integrate, slice));
}

// The same for a ray in no epipolar slice (the brute force, the correction at depth breaks).
float3 shadowedInscattering(ViewRay ray, float3 sunDir) {
    return shadowedInscatteringInSlice(ray, sunDir, 0);
}

#endif
