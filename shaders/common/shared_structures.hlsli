#ifndef FIRMAMENT_SHARED_STRUCTURES_HLSLI
#define FIRMAMENT_SHARED_STRUCTURES_HLSLI
// The constant-buffer structures, one definition read by both HLSL and C++ (C++ includes
// this file; see src/gpu/SharedStructures.h). This file holds the frame's constants, which
// every technique reads; each technique keeps its own structures in its shader folder
// (<technique>/<technique>_structures.hlsli), read by C++ through a header in its source
// folder, and follows the same rules. Rules that keep the two layouts identical:
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

#endif
