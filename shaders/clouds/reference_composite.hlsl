// The clouds' path-traced reference over the frame (docs/clouds.md, "Path-traced reference"):
// the mean of the paths accumulated so far (clouds/trace_clouds.hlsl), blended with
// premultiplied alpha: C = L_clouds + T C_scene, T the share of first flights that reached the
// scene behind the clouds.
#include "clouds/cloud_structures.hlsli"
#include "common/fullscreen_triangle.hlsli"

cbuffer CloudReferenceBuffer : register(b3) { CloudReferenceConstants reference; };
Texture2D<float4> accumulated : register(t0);  // sums: rgb the light, a the paths that reached the scene

FullscreenVertex vs_main(uint vertexId : SV_VertexID) { return fullscreenTriangle(vertexId); }

// Runs after the pass that traced, with its constants: paths.x + 1 passes so far, in rounds of
// stride^2 (clouds/trace_clouds.hlsl). A pixel whose first turn has not come shows its block's
// first pixel, traced on the round's first pass.
float4 ps_main(FullscreenVertex input) : SV_Target {
    uint stride = reference.options.w;
    uint blockPixels = stride * stride;
    uint passes = reference.paths.x + 1;
    uint2 pixel = uint2(input.position.xy);
    uint phase = pixel.x % stride + (pixel.y % stride) * stride;
    if (phase >= passes) {
        pixel -= pixel % stride;
        phase = 0;
    }
    float4 sum = accumulated.Load(int3(pixel, 0));
    float paths = float(((passes - 1 - phase) / blockPixels + 1) * reference.paths.y);
    return float4(sum.rgb / paths, 1.0 - sum.a / paths);
}
