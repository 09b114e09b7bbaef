#ifndef FIRMAMENT_TERRAIN_MATERIAL_HLSLI
#define FIRMAMENT_TERRAIN_MATERIAL_HLSLI
// The terrain's materials, chosen by slope and altitude (docs/terrain.md): meadows on gentle
// slopes, rock on steep ones and above the tree line, snow above a snow line that wanders with
// noise and does not hold on slopes steeper than about 40 degrees. Albedos are diffuse
// reflectances in linear RGB, near measured values (fresh grass 0.1-0.2, granite 0.2-0.3,
// old snow 0.7-0.85); value noise varies them so that no two hillsides look alike.
#include "terrain/surface.hlsli"

static const float3 kMeadowAlbedo = float3(0.075, 0.105, 0.040);
static const float3 kDryGrassAlbedo = float3(0.170, 0.150, 0.085);
static const float3 kRockAlbedo = float3(0.230, 0.210, 0.190);
static const float3 kDarkRockAlbedo = float3(0.120, 0.110, 0.100);
static const float3 kSnowAlbedo = float3(0.780, 0.800, 0.840);

// steepness: 1 - cos(slope angle), 0 on flat ground; p: metres in the plane.
float3 terrainAlbedo(float altitude, float steepness, float2 p) {
    float large = valueNoise(p / 310.0, 8) * 0.5 + 0.5;  // patches of hundreds of metres
    float small = valueNoise(p / 23.0, 9) * 0.5 + 0.5;   // and of tens
    float3 meadow = lerp(kMeadowAlbedo, kDryGrassAlbedo, 0.25 + 0.35 * large + 0.2 * small);
    float3 rock = lerp(kDarkRockAlbedo, kRockAlbedo, saturate(small * 0.8 + large * 0.4));
    float treeLine = 1500.0 + 300.0 * large;
    float rockWeight = max(smoothstep(0.16, 0.28, steepness + 0.06 * small), 0.8 * smoothstep(treeLine, treeLine + 400.0, altitude));
    float3 albedo = lerp(meadow, rock, rockWeight);
    float snowLine = 2000.0 + 350.0 * (large - 0.5) + 120.0 * small;
    float snowWeight = smoothstep(snowLine, snowLine + 250.0, altitude) * (1.0 - smoothstep(0.20, 0.32, steepness));
    return lerp(albedo, kSnowAlbedo, snowWeight);
}

#endif
