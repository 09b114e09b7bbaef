#ifndef FIRMAMENT_LIGHTSHAFTS_EPIPOLAR_INPUTS_HLSLI
#define FIRMAMENT_LIGHTSHAFTS_EPIPOLAR_INPUTS_HLSLI
// What every pass of the epipolar sampling reads (src/lightshafts/EpipolarSampling.cpp binds
// the same table for each, less the pass's own outputs). Textures of the epipolar space are
// samples wide and slices high: texel (i, s) is sample i of slice s.
#include "atmosphere/atmosphere_structures.hlsli"
#include "lightshafts/lightshaft_structures.hlsli"
#include "shadows/shadow_structures.hlsli"

cbuffer FrameBuffer : register(b0) { FrameConstants frame; };
cbuffer AtmosphereBuffer : register(b1) { AtmosphereConstants atmosphere; };
cbuffer LightShaftBuffer : register(b2) { LightShaftConstants lightShafts; };
cbuffer ShadowBuffer : register(b3) { ShadowConstants shadows; };
cbuffer EpipolarBuffer : register(b4) { EpipolarConstants epipolar; };
cbuffer CloudShadowBuffer : register(b6) { CloudShadowConstants cloudShadow; };  // b5: march_cascades.hlsl's

Texture2D<float4> sceneRadiance : register(t0);  // the HDR frame before the light shafts
Texture2D<float> sceneDepth : register(t1);      // reversed Z, 0 where nothing was drawn
Texture2D<float4> netDensityLut : register(t2);
Texture3D<float4> singleScatteringLut : register(t3);
Texture3D<float4> highOrderScatteringLut : register(t4);
Texture3D<float4> multipleScatteringLut : register(t5);
Texture2D<float> shadowMap : register(t6);
Texture2D<float> cameraDepth : register(t7);          // camera-space depth per pixel (m; kSkyDepth where nothing was drawn)
Texture2D<float4> sliceEnds : register(t8);           // slices x 1: entry xy, exit zw (NDC)
Texture2D<float4> sampleCoordinates : register(t9);   // xy: NDC; z: camera-space depth; w: the depth buffer's value
Texture2D<float4> coarseInscattering : register(t10); // unshadowed in-scattering per unit irradiance
Texture2D<float4> epipolarExtinction : register(t11); // T(C -> end) along each sample's ray
Texture2D<uint2> interpolationSources : register(t12); // the two marched samples each sample is interpolated from
Texture2D<float4> marchedInscattering : register(t13); // in-scattering with shadows, at the marched samples
Texture2D<float4> interpolatedInscattering : register(t14); // in-scattering with shadows, at every sample
StructuredBuffer<uint> workList : register(t15);       // the pass's list: samples (i | s << 16) or pixels (x | y << 16)
Buffer<uint> workArguments : register(t16);            // its dispatch arguments: x, y, z groups, then the count
Texture2D<float4> sliceLines : register(t17);         // slices x cascades: each slice's line in each shadow map
Texture2D<float2> minMaxTree : register(t18);         // the 1D min/max trees (lightshafts/minmax_trees.hlsli)
// One cascade's part of a listed sample's march (march_cascades.hlsl): march x the lit length,
// y the first lit point (-1: none); scattering rgb single scattering (Integration).
struct CascadePartial {
    float4 march;
    float4 scattering;
};
StructuredBuffer<CascadePartial> cascadeParts : register(t19);
Texture2DArray<float4> cloudShadowMap : register(t20); // the clouds' transparency maps (shadows/cloud_shadow.hlsli)
#define FIRMAMENT_CLOUD_SHADOWS
SamplerState linearClamp : register(s0);
SamplerComparisonState shadowComparison : register(s1);

#include "lightshafts/epipolar_geometry.hlsli"

// Thread groups: 64 samples of one slice, 8 x 8 pixels, 128 entries of a list. A list's
// groups are dispatched in rows of at most 65535 (lightshafts/work_list_arguments.hlsl).
#define SAMPLE_GROUP 64
#define PIXEL_GROUP 8
#define LIST_GROUP 128
static const uint kListRow = 65535;

// The list entry of thread `id` (SV_DispatchThreadID) of a pass dispatched over a list, and
// its index in the list; false past its end.
bool listEntryAt(uint3 id, out uint entry, out uint index) {
    index = id.y * kListRow * LIST_GROUP + id.x;
    entry = 0;
    if (index >= workArguments[3]) return false;
    entry = workList[index];
    return true;
}

bool listEntry(uint3 id, out uint entry) {
    uint index;
    return listEntryAt(id, entry, index);
}

uint2 unpackEntry(uint entry) {
    return uint2(entry & 0xFFFF, entry >> 16);
}

uint packEntry(uint2 texel) {
    return texel.x | (texel.y << 16);
}

bool validSample(float4 coordinates) {
    return coordinates.x > 0.5 * kInvalidCoordinate;
}

float2 uvOfNdc(float2 ndc) {
    return float2(ndc.x * 0.5 + 0.5, 0.5 - ndc.y * 0.5);
}

// The pixel under a point of the screen.
int2 pixelAt(float2 ndc) {
    return clamp(int2(uvOfNdc(ndc) * frame.screen.xy), 0, int2(frame.screen.xy) - 1);
}

#endif
