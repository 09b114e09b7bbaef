#ifndef FIRMAMENT_SHARED_STRUCTURES_HLSLI
#define FIRMAMENT_SHARED_STRUCTURES_HLSLI
// The constant-buffer structures, one definition read by both HLSL and C++ (C++ includes
// this file; see src/gpu/SharedStructures.h). Rules that keep the two layouts identical:
//  - members are float4, uint4 or float4x4 only (HLSL never splits them across 16-byte
//    registers, so no hidden padding appears on either side), scalars packed into a float4
//    with the use of each component named in a comment;
//  - matrices are column-major on both sides (GLM's memory order, HLSL's default): mul(M, v)
//    in HLSL is M * v in C++;
//  - every structure is followed by FIRMAMENT_CONSTANT_BUFFER(name), a compile-time check in
//    C++ that its size is a multiple of 16 bytes, as Direct3D requires of constant buffers.

#ifdef __cplusplus
#define FIRMAMENT_CONSTANT_BUFFER(name) \
    static_assert(sizeof(name) % 16 == 0, #name " must be a multiple of 16 bytes to be a constant buffer")
#else
#define FIRMAMENT_CONSTANT_BUFFER(name)
#endif

// Per frame, bound to register b0 of every stage that needs it.
struct FrameConstants {
    float4x4 viewProjection;         // world (metres) to clip space
    float4x4 inverseViewProjection;  // clip space to world
    float4x4 clipToDirection;        // clip space to a world-space view direction (the camera's
                                     // translation left out, for precision far from the origin)
    float4 cameraPosition;           // xyz: metres; w: altitude above the ground (metres)
    float4 directionToSun;           // xyz: unit vector towards the sun; w: unused
    float4 screen;                   // xy: size in pixels; zw: 1 / size
    float4 time;                     // x: seconds since start; yzw: unused
    float4 sunIrradiance;            // rgb: the sun's irradiance above the atmosphere (relative
                                     // units: the atmosphere's tables are per unit of it); w: unused
    float4 planet;                   // x: Earth radius (m), its centre at (0, -x, 0); y: the half-width of
                                     // the square the terrain covers (m; 0 without terrain), zw: its
                                     // centre (x, z): the orientation grid's ground lies outside it
};
FIRMAMENT_CONSTANT_BUFFER(FrameConstants);

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

// atmosphere/*: the physical model (src/atmosphere/AtmosphereParameters.h), lengths in metres.
struct AtmosphereConstants {
    float4 earth;               // x: Earth radius; y: atmosphere height; z: radius of its top; w: unused
    float4 scaleHeights;        // x: Rayleigh; y: Mie; zw: unused
    float4 rayleighScattering;  // rgb: beta_R at sea level (1/m), also its extinction; w: unused
    float4 mieScattering;       // rgb: beta_M at sea level (1/m); w: Mie asymmetry g
    float4 mieExtinction;       // rgb: Mie extinction at sea level (1/m); w: unused
    float4 ozone;               // rgb: ozone absorption at the layer's peak (1/m), zero when off; w: unused
    float4 ozoneLayer;          // x: altitude of the peak; y: half width of the tent; zw: unused
    float4 scatteringLutSize;   // the 4D scattering LUT: altitude, view zenith, sun zenith, sun-view
    float4 netDensityLutSize;   // xy: the net density LUT: altitude, zenith; z: ambient light LUT width;
                                // w: directions on the sphere for the scattering integrals (J, ambient)
};
FIRMAMENT_CONSTANT_BUFFER(AtmosphereConstants);

// atmosphere/yusov/render.hlsl
struct YusovPassConstants {
    uint4 mode;  // x: single scattering (0 none, 1 integration, 2 table); y: integration steps;
                 // z: multiple scattering (0 none, 1 occluded: the multiple table alone, 2 unoccluded:
                 // single scattering plus the high-order table); w: unused
    float4 sun;  // x: cosine of the sun's angular radius; y: the disc's radiance per unit irradiance; zw: unused
};
FIRMAMENT_CONSTANT_BUFFER(YusovPassConstants);

// atmosphere/bruneton/*: Bruneton and Neyret 2008's tables (src/atmosphere/bruneton).
struct BrunetonConstants {
    float4 transmittanceSize;  // xy: transmittance table, zenith cosines (columns) and radii (rows); zw: unused
    float4 irradianceSize;     // xy: irradiance table, sun zenith cosines (columns) and radii (rows); zw: unused
    float4 inscatterSize;      // the 4D in-scatter table: x radii, y view zenith, z sun zenith, w sun-view
    float4 ground;             // x: the ground's average albedo; y: the scattering order being computed; zw: unused
};
FIRMAMENT_CONSTANT_BUFFER(BrunetonConstants);

// atmosphere/bruneton/render.hlsl
struct BrunetonPassConstants {
    uint4 view;  // x: 0 the whole frame, 1 only columns >= y (the split view's right side), 2 the
                 // difference |this - the frame already drawn|; y: the split's first column; zw: unused
    float4 sun;  // x: cosine of the sun's angular radius; y: the disc's radiance per unit irradiance; zw: unused
};
FIRMAMENT_CONSTANT_BUFFER(BrunetonPassConstants);

// atmosphere/yusov/precompute_*.hlsl: the part of a table one dispatch fills.
struct PrecomputeSliceConstants {
    uint4 range;  // x: first z slice; y: one past the last; zw: unused
};
FIRMAMENT_CONSTANT_BUFFER(PrecomputeSliceConstants);

// postfx/log_luminance.hlsl and postfx/light_adaptation.hlsl
struct SceneLuminanceConstants {
    float4 source;      // xy: size of the HDR frame in pixels; zw: unused
    float4 adaptation;  // x: weight of the measured value, 1 - exp(-dt / tau) (1: take it as
                        // it is); yzw: unused
};
FIRMAMENT_CONSTANT_BUFFER(SceneLuminanceConstants);

// postfx/tone_mapping.hlsl
struct ToneMappingConstants {
    uint4 mode;       // x: operator (ToneMapOperator's order); y: 1 = auto exposure from the adapted
                      // log-average luminance, 0 = manual; zw: unused
    float4 exposure;  // x: middle grey (key); y: 2^EV (the manual exposure, or the compensation on
                      // top of auto exposure); z: white point Lw; w: luminance saturation
};
FIRMAMENT_CONSTANT_BUFFER(ToneMappingConstants);

#endif
