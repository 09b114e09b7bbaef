// The scene's depth at the clouds' low resolution (Downscale; docs/clouds.md, "Low-resolution
// rendering"): each low-resolution pixel keeps the nearest depth of the factor x factor block it
// covers (the largest, depth being reversed), so that clouds are cut where any of the block's
// pixels is terrain; the bilateral upsample then takes, for each full-resolution pixel, the
// low-resolution samples whose depth is like its own.
#include "clouds/cloud_structures.hlsli"
#include "common/fullscreen_triangle.hlsli"

cbuffer UpsampleBuffer : register(b0) { CloudUpsampleConstants upsample; };
Texture2D<float> sceneDepth : register(t0);  // full resolution

FullscreenVertex vs_main(uint vertexId : SV_VertexID) { return fullscreenTriangle(vertexId); }

float ps_main(FullscreenVertex input) : SV_Target {
    uint factor = upsample.sizes.x;
    int2 first = int2(input.position.xy) * int(factor);
    float nearest = 0.0;
    for (uint y = 0; y < factor; ++y)
        for (uint x = 0; x < factor; ++x) nearest = max(nearest, sceneDepth.Load(int3(first + int2(x, y), 0)));
    return nearest;
}
