#ifndef FIRMAMENT_LIGHT_SPACE_HLSLI
#define FIRMAMENT_LIGHT_SPACE_HLSLI
// The light-space grid of the particles' opacity (Yusov 2014, "Computing light occlusion";
// docs/clouds.md, "Light occlusion"): an orthographic map seen from the sun over the particles'
// field, one tile per texel. Each tile lists the particles whose footprint covers it, ordered from
// the sun; a node is (the particle's slot, the next node, its centre's distance toward the sun as
// float bits). The head texture has a row more than the map, whose first texel, (0, n), counts the
// nodes asked for. The CPU twin is src/reference/SunColumnTwin.cpp.
#include "clouds/cloud_structures.hlsli"

cbuffer LightSpaceBuffer : register(b2) { CloudLightSpaceConstants lightSpace; };

static const uint kNoParticle = 0xffffffffu;

uint lightSpaceResolution() { return uint(lightSpace.right.w); }

// The point's place in the map: -1..1 along its x and y axes.
float2 lightSpacePosition(float3 world) {
    float3 offset = world - lightSpace.centre.xyz;
    return float2(dot(offset, lightSpace.right.xyz), dot(offset, lightSpace.up.xyz)) / lightSpace.centre.w;
}

// The tile (texel) under a point, as rasterization numbers them (y down).
int2 lightSpaceTile(float3 world) {
    float2 p = lightSpacePosition(world);
    return int2(floor(float2(p.x * 0.5 + 0.5, 0.5 - p.y * 0.5) * lightSpace.right.w));
}

// Distance along the sun from the map's centre: larger is nearer the sun.
float towardSun(float3 world) { return dot(world - lightSpace.centre.xyz, lightSpace.sun.xyz); }

#endif
