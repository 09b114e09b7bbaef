// The terrain (docs/terrain.md): one clipmap level per draw, a regular grid of cells around the
// camera whose vertex spacing doubles from level to level. The vertex shader places vertex
// SV_VertexID on the surface; near the level's outer edge it morphs into the surface of the next
// coarser level, so that on the edge every vertex lies on the coarser level's edge, and the
// coarser level takes the finer one's edge vertices into its own triangles: the two meet
// without cracks or T-junctions. The pixel shader shades with the height field's slopes and the detail
// noise's, a material by slope and altitude, the sun attenuated by the atmosphere and shadowed by
// the cascades and by the clouds' shadow map (Yusov 2014), and the ambient sky light (Yusov 2013,
// "Terrain shaders").
//   vs_main + ps_main: the HDR frame, with depth; GROUND_LIGHTING selects the tables (0 none,
//   1 Yusov's, 2 Bruneton's).
//   vs_depth: depth only, for the shadow cascades.
#ifndef GROUND_LIGHTING
#define GROUND_LIGHTING 0
#endif
#include "atmosphere/atmosphere_structures.hlsli"
#include "shadows/shadow_structures.hlsli"
#include "terrain/terrain_structures.hlsli"

cbuffer FrameBuffer : register(b0) { FrameConstants frame; };
cbuffer AtmosphereBuffer : register(b1) { AtmosphereConstants atmosphere; };
#if GROUND_LIGHTING == 3
cbuffer HillaireBuffer : register(b2) { HillaireConstants hillaire; };
#else
cbuffer BrunetonBuffer : register(b2) { BrunetonConstants bruneton; };
#endif
cbuffer TerrainBuffer : register(b3) { TerrainConstants terrain; };
cbuffer ShadowBuffer : register(b4) { ShadowConstants shadows; };
cbuffer ShadowCasterBuffer : register(b5) { ShadowCasterConstants caster; };
cbuffer CloudShadowBuffer : register(b6) { CloudShadowConstants cloudShadow; };

Texture2D<float> heightField : register(t0);
Texture2D<float2> slopeField : register(t1);  // (dh/dx, dh/dz), mip-mapped
Texture2D<float4> sunTransmittanceTable : register(t2);
Texture2D<float4> skyIrradianceTable : register(t3);
Texture2D<float> shadowMap : register(t4);
Texture2DArray<float4> cloudShadowMap : register(t5);
Texture2D<float> slopeSecondMoment : register(t6);  // E[|dh/dx, dh/dz|^2], mip-mapped
SamplerState linearClamp : register(s0);
SamplerState linearWrap : register(s1);
SamplerComparisonState shadowComparison : register(s2);

#include "terrain/ground_lighting.hlsli"
#include "terrain/material.hlsli"
#include "shadows/cascade_sampling.hlsli"
#include "shadows/cloud_shadow.hlsli"

// The world position of vertex `id` of the current level: a grid vertex, or a midpoint of the
// hole's edge (src/terrain/ClipmapMesh.h).
float3 clipmapVertex(uint id) {
    uint cells = terrain.grid.x;
    float spacing = terrain.level.z;
    uint mip = (uint)terrain.level.w;
    uint gridVertices = (cells + 1) * (cells + 1);
    if (id >= gridVertices) {
        // Halfway between two vertices on the hole's edge, where the finer level has a vertex of
        // its boundary: the mean of the two, computed as the finer level computes it.
        uint halfCells = cells / 2, k = id - gridVertices, side = k / halfCells;
        float t = (float)(k % halfCells) + 0.5;
        float2 hole = float2(terrain.grid.w & 0xffffu, terrain.grid.w >> 16);
        float2 cell = side == 0 ? float2(hole.x + t, hole.y)
                    : side == 1 ? float2(hole.x + halfCells, hole.y + t)
                    : side == 2 ? float2(hole.x + t, hole.y + halfCells)
                                : float2(hole.x, hole.y + t);
        float2 along = (side % 2 == 0 ? float2(0.5, 0.0) : float2(0.0, 0.5)) * spacing;
        float2 q = terrain.level.xy + cell * spacing;
        float qy = 0.5 * (surfaceY(terrain, heightField, q - along, spacing, mip) + surfaceY(terrain, heightField, q + along, spacing, mip));
        return float3(q.x, qy, q.y);
    }
    uint i = id % (cells + 1), j = id / (cells + 1);
    float2 p = terrain.level.xy + float2(i, j) * spacing;
    float y = surfaceY(terrain, heightField, p, spacing, mip);
    float morphCells = terrain.coarser.z;
    if (morphCells > 0.0) {
        // Cells to the level's outer edge; the morph weight reaches 1 there.
        float edge = (float)min(min(i, j), min(cells - i, cells - j));
        float weight = saturate(1.0 - edge / morphCells);
        if (weight > 0.0) {
            // The coarser level's surface here: its vertices sit on even indices (the origin is
            // on its grid), and between them its triangles interpolate linearly.
            float coarseSpacing = terrain.coarser.x;
            uint coarseMip = (uint)terrain.coarser.y;
            float2 odd = float2(i & 1u, j & 1u) * spacing;
            float coarseY;
            if (odd.x > 0.0 && odd.y > 0.0) {
                coarseY = 0.25 * (surfaceY(terrain, heightField, p + float2(-odd.x, -odd.y), coarseSpacing, coarseMip) +
                                  surfaceY(terrain, heightField, p + float2(odd.x, -odd.y), coarseSpacing, coarseMip) +
                                  surfaceY(terrain, heightField, p + float2(-odd.x, odd.y), coarseSpacing, coarseMip) +
                                  surfaceY(terrain, heightField, p + float2(odd.x, odd.y), coarseSpacing, coarseMip));
            } else {
                coarseY = 0.5 * (surfaceY(terrain, heightField, p - odd, coarseSpacing, coarseMip) +
                                 surfaceY(terrain, heightField, p + odd, coarseSpacing, coarseMip));
            }
            // On the edge exactly the coarser level's value (lerp could round it off by an ulp).
            y = weight >= 1.0 ? coarseY : lerp(y, coarseY, weight);
        }
    }
    return float3(p.x, y, p.y);
}

struct TerrainVertex {
    float4 position : SV_Position;
    float3 world : WORLD;
};

TerrainVertex vs_main(uint id : SV_VertexID) {
    TerrainVertex v;
    v.world = clipmapVertex(id);
    v.position = mul(frame.viewProjection, float4(v.world, 1.0));
    return v;
}

float4 vs_depth(uint id : SV_VertexID) : SV_Position {
    return mul(caster.worldToClip, float4(clipmapVertex(id), 1.0));
}

struct SurfaceSlope {
    float3 normal;
    float variance;  // of the slopes within the pixel's footprint, beyond the mean's
};

// The surface normal in world space: the height field's slopes (filtered by the hardware for
// the pixel's footprint), scaled by the range mask, plus the mask's own slope times the height
// (the product rule for h = mask * field), the detail noise's by central differences where a
// pixel resolves it, and the curvature of the Earth (the surface is y = h - drop(x, z)).
// The variance: the filtered second moment less the mean's square (LEAN mapping's moments,
// Olano and Baker 2010), scaled by the mask as the slopes are.
SurfaceSlope surfaceSlope(float2 p, float footprint) {
    float2 uv = (p / terrain.field.x + 0.5) * terrain.field.z;
    float mask = rangeMask(p);
    float2 fieldSlope = slopeField.Sample(linearWrap, uv);
    float2 slope = mask * fieldSlope + heightField.Sample(linearWrap, uv) * rangeMaskGradient(p);
    float variance = mask * mask * max(slopeSecondMoment.Sample(linearWrap, uv) - dot(fieldSlope, fieldSlope), 0.0);
    float detailSpacing = max(footprint, 0.5);
    if (detailSpacing < kDetailLongestWavelength * 0.5) {
        float d = 0.25;
        slope.x += (detailHeight(p + float2(d, 0.0), detailSpacing) - detailHeight(p - float2(d, 0.0), detailSpacing)) / (2.0 * d);
        slope.y += (detailHeight(p + float2(0.0, d), detailSpacing) - detailHeight(p - float2(0.0, d), detailSpacing)) / (2.0 * d);
    }
    float R = terrain.field.w;
    float2 curvature = p / sqrt(max(R * R - dot(p, p), 1.0));  // d(drop)/dx, d(drop)/dz
    slope -= curvature;
    SurfaceSlope s;
    s.normal = normalize(float3(-slope.x, 1.0, -slope.y));
    s.variance = variance;
    return s;
}

// Steepness 1 - cos(slope angle) for the materials, with the slopes a pixel averages over kept:
// the cosine of the root-mean-square slope, cos / sqrt(1 + variance / (1 + |mean slope|^2)), so
// that a far mountainside, whose filtered normal points nearly up, keeps the rock its slopes carry.
float filteredSteepness(SurfaceSlope s, float3 up) {
    float cosine = dot(s.normal, up);
    float meanSlopeSquared = 1.0 / max(cosine * cosine, 1e-4) - 1.0;
    return 1.0 - cosine * rsqrt(1.0 + s.variance / (1.0 + meanSlopeSquared));
}

float4 ps_main(TerrainVertex input) : SV_Target {
    float3 world = input.world;
    float2 p = world.xz;
    float footprint = length(fwidth(p));
    SurfaceSlope surface = surfaceSlope(p, footprint);
    float3 normal = surface.normal;
    float3 up = normalize(float3(p.x, world.y + terrain.field.w, p.y));
    float altitude = world.y + earthDrop(p, terrain.field.w);
    float3 toSun = frame.directionToSun.xyz;
    float steepness = filteredSteepness(surface, up);
    float3 albedo = terrainAlbedo(altitude, steepness, p, footprint);

    float viewDepth = dot(world - frame.cameraPosition.xyz, shadows.cameraForward.xyz);
    int cascade = -1;
    float visibility = shadows.mode.x > 0 ? sunVisibility(world, normal, viewDepth, cascade) : 1.0;
    if (shadows.mode.w != 0) albedo *= cascadeTint(cascade);
    float clouds = cloudTransmittance(world);

    switch (terrain.grid.z) {
        case 1: return float4(albedo, 1.0);
        case 2: return float4(normal * 0.5 + 0.5, 1.0);
        case 3: return float4(cascadeTint((int)terrain.grid.y % 8), 1.0);
        case 4: return float4(clouds, clouds, clouds, 1.0);
        default: break;
    }
    GroundLight light = groundLight(altitude, dot(up, toSun));
    float3 radiance = lambertianRadiance(albedo, normal, up, toSun, visibility * clouds, light) * frame.sunIrradiance.rgb;
    return float4(radiance, 1.0);
}
