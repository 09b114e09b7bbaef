#ifndef FIRMAMENT_CLOUD_STRUCTURES_HLSLI
#define FIRMAMENT_CLOUD_STRUCTURES_HLSLI
// The clouds' structures, one definition read by HLSL and C++ (src/clouds/CloudStructures.h),
// under the rules of common/shared_structures.hlsli.
#include "common/shared_structures.hlsli"

// The fragments one pixel's resolve sorts and blends (clouds/resolve_fragments.hlsl); the
// farthest beyond it are dropped. The lists' pool holds this many per pixel at first
// (src/clouds/VolumeBlendingPass.h).
static const uint kMaxPixelFragments = 32;

// The cell grid, the density map and the particles' generation (clouds/cloud_field.hlsli;
// docs/clouds.md). Built by CloudField::constants().
struct CloudFieldConstants {
    float4 grid;       // x: ring 0's cell size (m); y: the layer's middle altitude (m); z: its thickness (m); w: particle distance (m)
    uint4 layout;      // x: rings; y: cells along a ring's side (D); z: layers; w: cells in the grid
    uint4 centre;      // xy: the grid's centre in the outer ring's cells (x, z; two's complement ints); z: particle capacity; w: unused
    float4 coverage;   // x: cloudiness; y: 1 / the coarse tap's period (1/m); z: 1 / the fine tap's period; w: the density map's side (texels)
    float4 wind;       // xy: the coarse tap's wind offset (m, within its period); zw: the fine tap's
    float4 animation;  // x, y: phases (radians) of the particles' size and density pulses; zw: unused
    float4 tableSizes; // the optical depth table's N0 (entry zenith), N1 (entry azimuth), N2 (direction zenith), N3 (direction azimuth)
};
FIRMAMENT_CONSTANT_BUFFER(CloudFieldConstants);

// One merge pass of the particles' sort (clouds/merge_sorted.hlsl).
struct CloudSortConstants {
    uint4 merge;  // x: the length of the sorted runs this pass merges in pairs; yzw: unused
};
FIRMAMENT_CONSTANT_BUFFER(CloudSortConstants);

// The particle's tables (clouds/precompute_*.hlsl).
struct ParticleTableConstants {
    uint4 sizes;    // the optical depth table's N0 (entry zenith), N1 (entry azimuth), N2 (direction zenith), N3 (direction azimuth)
    uint4 options;  // x: density method (0 radial fall-off and noise, 1 thresholded noise, 2 pyroclastic); y: steps
                    // along a chord; z: the first z slice of this unit of work; w: unused
};
FIRMAMENT_CONSTANT_BUFFER(ParticleTableConstants);

// The clouds' shading (clouds/shade_particles.hlsl): the atmosphere's render modes, the
// scattering table's size and the per-pixel lists' capacity.
struct CloudShadingConstants {
    uint4 modes;       // x: single scattering mode, y: multiple scattering mode, z: integration steps (the atmosphere's); w: unused
    float4 scattering; // the particle scattering table's texels: x entry angles, y view azimuths, z view zeniths; w: optical radii (layers)
    float4 light;      // x: the scattering table's first optical radius (each next layer doubles it); y: Multiple scattering (0 deck diffusion, 1 the particle table, 2 deck diffusion's solved slab); z: the solved slab table's thinnest slab; w: Light terms (0 all, 1 the sun's scattered once, 2 more than once, 3 the sky's, 4 none)
    float4 deck;       // deck diffusion's solved slab table (src/clouds/DeckDiffusionTable.h): x cosines, y depths, z thicknesses, w thicknesses per octave
    uint4 blending;    // x: the per-pixel lists' node capacity, y: the row of their counters (clouds/fragment_lists.hlsli); zw: unused
    float4 target;     // the clouds' target (the frame's, or its low-resolution one): width, height, 1 / width, 1 / height
};

// The light-space grid of the particles' opacity (clouds/light_space.hlsli): an orthographic map
// seen from the sun. Built by lightSpaceConstants() (src/clouds/LightSpace.h).
struct CloudLightSpaceConstants {
    float4 centre;  // xyz: the map's centre (world, m); w: its half-width (m)
    float4 right;   // xyz: the map's x axis (unit, across the sun); w: tiles along a side
    float4 up;      // xyz: its y axis (unit, across the sun); w: the early exit's transmittance (0: none)
    float4 sun;     // xyz: the direction to the sun (unit); w: the node pool's capacity
};
FIRMAMENT_CONSTANT_BUFFER(CloudLightSpaceConstants);

// "Shafts from clouds: shadow map" (clouds/merge_cloud_shadows.hlsl): one shadow cascade, into
// which the clouds' light-space map is drawn as casters.
struct CloudShadowMergeConstants {
    float4x4 clipToWorld;  // the cascade's clip space (x, y in -1..1, depth 0..1) to the world
    float4x4 worldToClip;  // the cascade's orthographic view-projection
};
FIRMAMENT_CONSTANT_BUFFER(CloudShadowMergeConstants);

// The clouds' low-resolution passes (clouds/downsample_depth.hlsl, upsample_clouds.hlsl).
struct CloudUpsampleConstants {
    uint4 sizes;  // x: the downscale factor; y, z: the low-resolution target's width and height; w: unused
};
FIRMAMENT_CONSTANT_BUFFER(CloudUpsampleConstants);
FIRMAMENT_CONSTANT_BUFFER(CloudShadingConstants);

// The clouds' path-traced reference (clouds/reference_index.hlsl, clouds/trace_clouds.hlsl;
// docs/clouds.md, "Path-traced reference"). Built by CloudReference (src/clouds/CloudReference.h).
struct CloudReferenceConstants {
    uint4 paths;    // x: passes since the accumulation started over, before this one; y: paths per pixel it adds; z: a seed; w: rays (the tests' kernel)
    uint4 options;  // x: the density method (as ParticleTableConstants.options.x); y: 1 with the ground's bounce; z: the bounce limit; w: the pixel stride (a pass traces one pixel of every w x w block)
    uint4 modes;    // Yusov's render modes: x single scattering, y multiple, z integration steps (as CloudShadingConstants.modes); w: unused
    float4 target;  // the frame's width, height, 1 / width, 1 / height
    float4 light;   // the tests' constant lighting (CLOUD_ATMOSPHERE 0): rgb the sun's irradiance, w the sky's radiance (grey)
    float4 ground;  // the tests' ground: x its height (y, m), yzw its albedo (CLOUD_ATMOSPHERE 0; w of options.y)
};
FIRMAMENT_CONSTANT_BUFFER(CloudReferenceConstants);

#ifndef __cplusplus
// A particle as generation writes it (StructuredBuffer, 32 bytes).
struct CloudParticle {
    float4 centre;  // xyz: world position (m); w: horizontal radius (m)
    float4 shape;   // x: vertical radius (m), along the planet's normal; y: density (0..1, animated);
                    // z: azimuth (radians) that turns the particle's noise; w: ring
};
#endif

#endif
