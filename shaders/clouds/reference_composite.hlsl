// The clouds' path-traced reference over the frame (docs/clouds.md, "Path-traced reference"):
// the mean of the paths accumulated so far (clouds/trace_clouds.hlsl), blended with
// premultiplied alpha: C = L_clouds + T C_scene, T the share of first flights that reached the
// scene behind the clouds.
#include "clouds/cloud_structures.hlsli"
#include "common/fullscreen_triangle.hlsli"

cbuffer CloudReferenceBuffer : register(b3) { CloudReferenceConstants reference; };
Texture2D<float4> accumulated : register(t0);  // sums: rgb the light, a the paths that reached the scene

FullscreenVertex vs_main(uint vertexId : SV_VertexID) { return fullscreenTriangle(vertexId); }

float4 ps_main(FullscreenVertex input) : SV_Target {
    float4 sum = accumulated.Load(int3(input.position.xy, 0));
    float paths = max(float(reference.paths.x + reference.paths.y), 1.0);
    return float4(sum.rgb / paths, 1.0 - sum.a / paths);
}
