// The per-pixel lists' resolve (docs/clouds.md, "Blending"): each pixel's fragments, at most
// kMaxPixelFragments of them nearest the camera by their back distance, sorted, then added from
// the farthest with volume-aware blending, so that a fragment pushed behind is never overlapped
// by a later one; the result blended over the scene with premultiplied alpha. The CPU twin is
// blendVolumes() in src/reference/VolumeBlendingTwin.cpp.
#include "common/fullscreen_triangle.hlsli"
#include "clouds/fragment_lists.hlsli"

RWTexture2D<uint> fragmentHeads : register(u1);  // the counters in the row below the target's
StructuredBuffer<FragmentNode> fragmentNodes : register(t0);
cbuffer ResolveBuffer : register(b0) { uint4 resolve; };  // x: the counters' row (the target's height)

FullscreenVertex vs_main(uint vertexId : SV_VertexID) { return fullscreenTriangle(vertexId); }

float4 ps_main(FullscreenVertex input) : SV_Target {
    uint node = fragmentHeads[uint2(input.position.xy)];
    if (node == kNoFragment) discard;
    // Insertion into two arrays ordered by increasing back distance.
    float4 colourExtinction[kMaxPixelFragments];
    float2 extent[kMaxPixelFragments];
    uint count = 0, dropped = 0;
    // A list never holds more nodes than the pool; the bound only guards a corrupt link.
    for (uint guard = 0; guard < 65536 && node != kNoFragment; ++guard) {
        FragmentNode n = fragmentNodes[node];
        node = n.next;
        if (count == kMaxPixelFragments) {
            ++dropped;
            if (n.back >= extent[kMaxPixelFragments - 1].y) continue;
            --count;  // the farthest kept makes room
        }
        uint k = count;
        while (k > 0 && extent[k - 1].y > n.back) {
            colourExtinction[k] = colourExtinction[k - 1];
            extent[k] = extent[k - 1];
            --k;
        }
        colourExtinction[k] = float4(n.colour, n.extinction);
        extent[k] = float2(n.front, n.back);
        ++count;
    }
    if (dropped > 0) {
        uint before;
        InterlockedAdd(fragmentHeads[uint2(1, resolve.x)], dropped, before);
    }
    VolumeBlend blend = emptyVolumeBlend();
    for (uint j = count; j > 0; --j) {
        ParticleFragment f;
        f.colour = colourExtinction[j - 1].rgb;
        f.extinction = colourExtinction[j - 1].a;
        f.front = extent[j - 1].x;
        f.back = extent[j - 1].y;
        addFragment(blend, f);
    }
    BlendedLight light = resolveVolumeBlend(blend);
    return float4(light.light, 1.0 - light.transmittance);
}
