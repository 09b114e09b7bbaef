// Appends synthetic fragments to the per-pixel lists (clouds/fragment_lists.hlsli), one thread
// per fragment, for the resolve's test against the CPU twin.
#define FRAGMENT_LISTS_APPEND
#include "clouds/fragment_lists.hlsli"

struct SyntheticFragment {
    float4 colourExtinction;
    float2 extent;  // front, back
    uint2 pixel;
};
StructuredBuffer<SyntheticFragment> fragments : register(t0);
cbuffer Probe : register(b0) { uint4 probe; };  // x: fragments; y: the pool's capacity; z: the draw; w: the counters' row

[numthreads(64, 1, 1)]
void main(uint3 id : SV_DispatchThreadID) {
    if (id.x >= probe.x) return;
    SyntheticFragment s = fragments[id.x];
    ParticleFragment f;
    f.colour = s.colourExtinction.rgb;
    f.extinction = s.colourExtinction.a;
    f.front = s.extent.x;
    f.back = s.extent.y;
    appendFragment(s.pixel, f, probe.y, probe.w);
}

// The same through the pixel stage, as the particles' pass appends: a full-screen triangle drawn
// with no render target, each pixel appending one fragment made from its position and probe.z.
#include "common/fullscreen_triangle.hlsli"

FullscreenVertex vs_main(uint vertexId : SV_VertexID) { return fullscreenTriangle(vertexId); }

void ps_main(FullscreenVertex input) {
    uint2 pixel = uint2(input.position.xy);
    ParticleFragment f;
    f.colour = float3(pixel.x + 1, pixel.y + 1, probe.z + 1);
    f.extinction = 0.001 * (probe.z + 1);
    f.front = 100.0 + 10.0 * probe.z;
    f.back = f.front + 150.0;
    appendFragment(pixel, f, probe.y, probe.w);
}
