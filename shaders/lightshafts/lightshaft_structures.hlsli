#ifndef FIRMAMENT_LIGHTSHAFT_STRUCTURES_HLSLI
#define FIRMAMENT_LIGHTSHAFT_STRUCTURES_HLSLI
// The light shafts' constant-buffer structures, one definition read by HLSL and C++
// (src/lightshafts/LightShaftStructures.h), under the rules of common/shared_structures.hlsli.
#include "common/shared_structures.hlsli"

// lightshafts/ray_march.hlsli and the passes that march.
struct LightShaftConstants {
    uint4 mode;     // x: single scattering (0 none, 1 integration, 2 table); y: integration steps;
                    // z: multiple scattering (0 none, 1 occluded, 2 unoccluded); w: first cascade to march
    uint4 options;  // x: lighting only (the in-scattered light alone); yzw: unused
    float4 march;   // x: where the shafts end (m from the camera); y: most steps in one cascade; zw: unused
    float4 sun;     // x: cosine of the sun's angular radius; y: the disc's radiance per unit irradiance; zw: unused
};
FIRMAMENT_CONSTANT_BUFFER(LightShaftConstants);

#endif
