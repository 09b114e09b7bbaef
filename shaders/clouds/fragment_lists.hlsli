#ifndef FIRMAMENT_FRAGMENT_LISTS_HLSLI
#define FIRMAMENT_FRAGMENT_LISTS_HLSLI
// Per-pixel lists of particle fragments, the exact fallback of volume-aware blending where the
// device has no rasterizer-ordered views (docs/clouds.md, "Blending"): a head index per pixel and
// a bounded pool of nodes, each linking to the pixel's previous head. The particles' pass appends
// in whatever order the pixels are shaded; clouds/resolve_fragments.hlsl sorts each list and
// blends it. The head texture has one row more than the target, whose first texels count:
// (0, height) the nodes asked for (those past the pool's capacity are dropped), (1, height) the
// fragments the resolve drops beyond kMaxPixelFragments in one pixel: two views bound, not three.
#include "clouds/cloud_structures.hlsli"
#include "clouds/volume_blending.hlsli"

struct FragmentNode {
    float3 colour;
    float extinction;
    float front;
    float back;
    uint next;
};

static const uint kNoFragment = 0xffffffffu;

#ifdef FRAGMENT_LISTS_APPEND
RWTexture2D<uint> fragmentHeads : register(u1);
RWStructuredBuffer<FragmentNode> fragmentNodes : register(u2);

// `countersRow`: the target's height.
void appendFragment(uint2 pixel, ParticleFragment f, uint capacity, uint countersRow) {
    uint slot;
    InterlockedAdd(fragmentHeads[uint2(0, countersRow)], 1, slot);
    if (slot >= capacity) return;
    uint previous;
    InterlockedExchange(fragmentHeads[pixel], slot, previous);
    FragmentNode node;
    node.colour = f.colour;
    node.extinction = f.extinction;
    node.front = f.front;
    node.back = f.back;
    node.next = previous;
    fragmentNodes[slot] = node;
}
#endif

#endif
