#ifndef FIRMAMENT_TERRAIN_MATERIAL_HLSLI
#define FIRMAMENT_TERRAIN_MATERIAL_HLSLI
// The terrain's materials, chosen by slope and altitude (docs/terrain.md): meadows on gentle
// slopes, rock on steep ones and above the tree line, snow above a snow line that wanders with
// noise and does not hold on slopes steeper than about 40 degrees. Albedos are diffuse
// reflectances in linear RGB, near measured values (fresh grass 0.1-0.2, granite 0.2-0.3,
// old snow 0.7-0.85); value noise varies them so that no two hillsides look alike, filtered by
// the pixel's footprint so that it never aliases.
#include "terrain/surface.hlsli"

static const float3 kMeadowAlbedo = float3(0.075, 0.105, 0.040);
static const float3 kDryGrassAlbedo = float3(0.170, 0.150, 0.085);
static const float3 kRockAlbedo = float3(0.230, 0.210, 0.190);
static const float3 kDarkRockAlbedo = float3(0.120, 0.110, 0.100);
static const float3 kSnowAlbedo = float3(0.780, 0.800, 0.840);

// Value noise remapped to [0, 1], faded to its mean 0.5 where a pixel (of `footprint` metres)
// spans half a wavelength or more: unfiltered noise would alias into speckle from afar.
float filteredNoise(float2 p, float wavelength, uint octave, float footprint) {
    float detail = saturate(2.0 - 4.0 * footprint / wavelength);
    return lerp(0.5, valueNoise(p / wavelength, octave) * 0.5 + 0.5, detail);
}

// steepness: 1 - cos(slope angle), 0 on flat ground; p: metres in the plane; footprint: the
// pixel's size on the ground in metres.
float3 terrainAlbedo(float altitude, float steepness, float2 p, float footprint) {
    float large = filteredNoise(p, 310.0, 8, footprint);  // patches of hundreds of metres
    float small = filteredNoise(p, 23.0, 9, footprint);   // and of tens
    // Regions of tens of kilometres, on lattices that do not repeat with the height field's
    // tile: from high up they break the tile's repetition.
    float region = filteredNoise(p, 41000.0, 10, footprint) * 0.6 + filteredNoise(p, 13700.0, 11, footprint) * 0.4;
    float3 meadow = lerp(kMeadowAlbedo, kDryGrassAlbedo, saturate(0.1 + 0.5 * region + 0.25 * large + 0.15 * small));
    float3 rock = lerp(kDarkRockAlbedo, kRockAlbedo, saturate(small * 0.8 + large * 0.4 - 0.3 * (region - 0.5)));
    float treeLine = 1400.0 + 300.0 * large + 300.0 * region;
    float rockWeight = max(smoothstep(0.16, 0.28, steepness + 0.06 * small), 0.8 * smoothstep(treeLine, treeLine + 400.0, altitude));
    float3 albedo = lerp(meadow, rock, rockWeight);
    float snowLine = 1850.0 + 350.0 * (large - 0.5) + 120.0 * small + 400.0 * (region - 0.5);
    float snowWeight = smoothstep(snowLine, snowLine + 250.0, altitude) * (1.0 - smoothstep(0.20, 0.32, steepness));
    return lerp(albedo, kSnowAlbedo, snowWeight);
}

#endif
