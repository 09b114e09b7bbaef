// The rasterizer-ordered path (clouds/ordered_blending.hlsli) with many overlapping fragments per
// pixel from one draw: probe.x full-screen triangles, triangle k merging fragment k of the buffer
// at t0 (its colour scaled by the pixel's position). Only the views' ordering keeps triangle k's
// merge after triangle k - 1's within the draw, so a device without rasterizer-ordered views
// cannot run this test (FragmentListsTest skips it there).
#include "clouds/ordered_blending.hlsli"
#include "common/fullscreen_triangle.hlsli"

cbuffer Probe : register(b0) { uint4 probe; };  // x: the triangles in the draw

struct FragmentInput {
    float4 colourExtinction;
    float2 extent;
    uint2 unused;
};
StructuredBuffer<FragmentInput> fragments : register(t0);

struct OrderedVertex {
    FullscreenVertex fullscreen;
    nointerpolation uint triangleIndex : TRIANGLE;
};

OrderedVertex vs_main(uint vertexId : SV_VertexID) {
    OrderedVertex v;
    v.fullscreen = fullscreenTriangle(vertexId % 3);
    v.triangleIndex = vertexId / 3;
    return v;
}

float4 ps_main(OrderedVertex input) : SV_Target {
    uint2 pixel = uint2(input.fullscreen.position.xy);
    FragmentInput source = fragments[input.triangleIndex];
    ParticleFragment f;
    f.colour = source.colourExtinction.rgb * float3(1.0 + 0.25 * pixel.x, 1.0 + 0.25 * pixel.y, 1.0);
    f.extinction = source.colourExtinction.a;
    f.front = source.extent.x;
    f.back = source.extent.y;
    BlendedLight behind = mergeInPixelOrder(pixel, f);
    return float4(behind.light, 1.0 - behind.transmittance);
}
