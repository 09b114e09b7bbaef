#ifndef FIRMAMENT_ATMOSPHERE_STRUCTURES_HLSLI
#define FIRMAMENT_ATMOSPHERE_STRUCTURES_HLSLI
// The atmosphere's constant-buffer structures (both models), one definition read by HLSL and C++
// (src/atmosphere/AtmosphereStructures.h), under the rules of common/shared_structures.hlsli.
#include "common/shared_structures.hlsli"

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
                 // z: multiple scattering (0 none, 1 occluded, 2 unoccluded: docs/atmosphere.md,
                 // "Render modes"); w: unused
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
    float4 sun;  // x: cosine of the sun's angular radius; y: the disc's radiance per unit irradiance; zw: unused
};
FIRMAMENT_CONSTANT_BUFFER(BrunetonPassConstants);

// atmosphere/yusov/precompute_*.hlsl: the part of a table one dispatch fills.
// atmosphere/hillaire/precompute_*.hlsl: Hillaire 2020's tables' sizes and sampling.
struct HillaireConstants {
    float4 transmittanceSize;       // xy: texels along mu and r; zw: unused
    float4 multipleScatteringSize;  // xy: texels along mu_s and r; z: directions over the sphere; w: steps along each
    float4 skyView;                 // xy: texels along the longitude and the latitude; z: steps along each view; w: unused
    float4 aerialPerspective;       // x: froxels along each axis; y: the volume's depth (m); z: steps per slice;
                                    // w: steps of a view marched per pixel (beyond the volume, from space)
    float4 irradianceSize;          // xy: the sky irradiance table, texels along mu_s and r; z: directions over the
                                    // sphere; w: steps along each
};
FIRMAMENT_CONSTANT_BUFFER(HillaireConstants);

// atmosphere/hillaire/render.hlsl
struct HillairePassConstants {
    float4 sun;  // x: cosine of the sun's angular radius; y: the disc's radiance per unit irradiance; zw: unused
};
FIRMAMENT_CONSTANT_BUFFER(HillairePassConstants);

struct PrecomputeSliceConstants {
    uint4 range;  // x: first z slice; y: one past the last; zw: unused
};
FIRMAMENT_CONSTANT_BUFFER(PrecomputeSliceConstants);

#endif
