#ifndef FIRMAMENT_SHADOW_STRUCTURES_HLSLI
#define FIRMAMENT_SHADOW_STRUCTURES_HLSLI
// The shadow cascades' constant-buffer structures, one definition read by HLSL and C++
// (src/frame/ShadowStructures.h), under the rules of common/shared_structures.hlsli.
#include "common/shared_structures.hlsli"

// shadows/*: the cascaded shadow maps (src/shadows/CascadedShadowMaps.h), for the passes that
// read them (terrain now; light shafts later). Cascade i covers view depths [split i, split i+1].
// The cascades are tiles of one depth texture (an atlas), up to four to a row: cascade i is
// tile (i % 4, i / 4).
struct ShadowConstants {
    float4x4 worldToShadow[8];  // world to (u, v, depth) in cascade i's own tile: u, v in [0, 1], depth in [0, 1]
    float4 splits[3];           // view-space depth of the cascades' edges: split i is component i % 4
                                // of splits[i / 4]; 9 values for 8 cascades
    float4 texelWorldSize[2];   // the world size of one texel of cascade i, component i % 4 of [i / 4]
    float4 cameraForward;       // xyz: the camera's forward unit vector (view depth = dot(p - camera, this))
    uint4 mode;                 // x: cascade count; y: smooth shadows (5-tap PCF); z: best cascade
                                // search; w: show cascades (tint)
    float4 map;                 // x: a cascade's resolution (texels); y: 1 / resolution; z: depth bias; w: normal offset (texels)
    float4 atlas;               // x: tiles per row; y: rows; z: 1 / tiles per row; w: 1 / rows
};
FIRMAMENT_CONSTANT_BUFFER(ShadowConstants);

// shadows/cascade_depth.hlsl: the cascade a depth pass draws into.
struct ShadowCasterConstants {
    float4x4 worldToClip;  // the cascade's orthographic view-projection
};
FIRMAMENT_CONSTANT_BUFFER(ShadowCasterConstants);

// shadows/cloud_shadow.hlsli: the clouds' light-space transparency maps (src/clouds/CloudShadowMap.h),
// orthographic views from the sun over the camera: a near map of fine texels and a far one over
// the whole particle field, two slices of one texture array. Each texel holds, for the sun's ray
// through it, the clouds' transmittance and the stretch of the ray they occupy, as distances
// toward the sun from its map's centre.
struct CloudShadowConstants {
    float4 centre;     // xyz: the near map's centre (world, m); w: its half-width (m)
    float4 right;      // xyz: the maps' x axis (unit, across the sun); w: texels along a side
    float4 up;         // xyz: their y axis (unit, across the sun); w: 1 when the maps hold this frame's clouds, 0 for none
    float4 sun;        // xyz: the direction to the sun (unit); w: the width of each map's fade at its edge (share of its half-width)
    float4 farCentre;  // xyz: the far map's centre; w: its half-width (m)
};
FIRMAMENT_CONSTANT_BUFFER(CloudShadowConstants);

#endif
