// The rasterizer-ordered path's resolve (docs/clouds.md, "Blending"): the fragment each pixel's
// views still hold, blended over what the particles' pass pushed behind it into the target.
#include "common/fullscreen_triangle.hlsli"
#include "clouds/volume_blending.hlsli"

RWTexture2D<float4> storedColour : register(u1);  // colour, extinction
RWTexture2D<float2> storedExtent : register(u2);  // front, back (back <= front: none)

FullscreenVertex vs_main(uint vertexId : SV_VertexID) { return fullscreenTriangle(vertexId); }

float4 ps_main(FullscreenVertex input) : SV_Target {
    uint2 pixel = uint2(input.position.xy);
    float2 extent = storedExtent[pixel];
    if (extent.y <= extent.x) discard;
    float4 colour = storedColour[pixel];
    ParticleFragment stored;
    stored.colour = colour.rgb;
    stored.extinction = colour.a;
    stored.front = extent.x;
    stored.back = extent.y;
    BlendedLight light = blendOver(stored, noLight());
    return float4(light.light, 1.0 - light.transmittance);
}
