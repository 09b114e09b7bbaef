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
    float4 march;   // x: where the shafts end (m from the camera); y: most steps in one cascade; z: scattering scale; w: unused
    float4 sun;     // x: cosine of the sun's angular radius; y: the disc's radiance per unit irradiance; zw: unused
};
FIRMAMENT_CONSTANT_BUFFER(LightShaftConstants);

// The epipolar sampling's passes (lightshafts/epipolar_*.hlsl; docs/lightshafts.md).
struct EpipolarConstants {
    uint4 sampling;        // x: slices; y: samples per slice; z: initial sample step; w: epipole sampling density
    uint4 options;         // x: refinement criterion (0 depth, 1 in-scattering); y: optimize sample locations;
                           // z: correction at depth breaks; w: show depth breaks
    uint4 modes;           // x: extinction (0 per pixel, 1 from epipolar space); yzw: unused
    float4 epipole;        // xy: the sun's projection in NDC (the anti-epipole's with the sun behind the camera),
                           // at most 100 from the centre; z: 1 when it lies on the screen; w: 1 when the sun is behind
    float4 refinement;     // x: threshold; y: the in-scattering criterion's floor (per unit irradiance); z: the Depth criterion's threshold; w: unused
    float4 cameraForward;  // xyz: the camera's forward axis, along which camera-space depth counts; w: unused
    uint4 trees;           // the 1D min/max trees: x: walked (built this frame); y: entries of level 0 (the cascades'
                           // resolution); z: the top level, log2(y); w: 16-bit unorm (else 32-bit float)
};
FIRMAMENT_CONSTANT_BUFFER(EpipolarConstants);

// The march cascade by cascade (lightshafts/march_cascades.hlsl, combine_cascades.hlsl) and the
// list's dispatch arguments (work_list_arguments.hlsl).
struct CascadePassConstants {
    uint4 cascades;  // x: the first cascade the dispatch marches, counted from the first to march; y: the parts'
                 // entries per cascade (the list's capacity); z: the cascades of an instanced dispatch; w: unused
};
FIRMAMENT_CONSTANT_BUFFER(CascadePassConstants);

#endif
