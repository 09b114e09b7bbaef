#ifndef FIRMAMENT_TERRAIN_STRUCTURES_HLSLI
#define FIRMAMENT_TERRAIN_STRUCTURES_HLSLI
// The terrain's constant-buffer structures, one definition read by HLSL and C++
// (src/terrain/TerrainStructures.h), under the rules of common/shared_structures.hlsli.
#include "common/shared_structures.hlsli"

// terrain/*: the terrain's height field and one clipmap level (src/terrain/Terrain.h), lengths in metres.
struct TerrainConstants {
    float4 field;    // x: height-field sample spacing; y: samples per side; z: 1 / samples per side; w: Earth radius
    float4 level;    // xy: the level's grid origin (x, z); z: its vertex spacing; w: its height-field mip
    float4 coarser;  // x: the next coarser level's spacing; y: its mip; z: cells over which vertices morph
                     // into the coarser level at the outer edge (0: no coarser level); w: unused
    uint4 grid;      // x: cells per side of a level; y: the level's index; z: material view (0 shaded,
                     // 1 albedo, 2 normals, 3 levels); w: the hole's first cell, x in the low 16
                     // bits and z in the high 16 (its edge's midpoints: src/terrain/ClipmapMesh.h)
};
FIRMAMENT_CONSTANT_BUFFER(TerrainConstants);

#endif
