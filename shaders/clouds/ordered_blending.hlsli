#ifndef FIRMAMENT_ORDERED_BLENDING_HLSLI
#define FIRMAMENT_ORDERED_BLENDING_HLSLI
// Volume-aware blending in primitive order through rasterizer-ordered views (docs/clouds.md,
// "Blending"; Intel's PixelSync in Yusov 2014): each pixel's views hold the stored fragment, the
// target holds what has been pushed behind it. The same steps as addFragment() in
// clouds/volume_blending.hlsli, with the fragment pushed behind returned for the target's
// premultiplied blending; clouds/resolve_ordered.hlsl blends the fragment left stored.
#include "clouds/volume_blending.hlsli"

// The stored fragment: colour and extinction; front and back (back <= front: none stored).
RasterizerOrderedTexture2D<float4> storedColour : register(u1);
RasterizerOrderedTexture2D<float2> storedExtent : register(u2);

BlendedLight mergeInPixelOrder(uint2 pixel, ParticleFragment fragment) {
    float4 colour = storedColour[pixel];
    float2 extent = storedExtent[pixel];
    ParticleFragment stored;
    stored.colour = colour.rgb;
    stored.extinction = colour.a;
    stored.front = extent.x;
    stored.back = extent.y;
    BlendedLight behind = noLight();
    if (extent.y <= extent.x) {
        stored = fragment;
    } else if (fragment.back <= stored.front) {
        behind = blendOver(stored, behind);
        stored = fragment;
    } else if (fragment.front >= stored.back) {
        behind = blendOver(fragment, behind);
    } else {
        stored = mergeOverlapping(stored, fragment);
    }
    storedColour[pixel] = float4(stored.colour, stored.extinction);
    storedExtent[pixel] = float2(stored.front, stored.back);
    return behind;
}

#endif
