// Show particles: optical depth. Each particle white, with the transparency exp(-tau) of its
// optical depth along the view ray from the particle's table (Yusov 2014, "Pre-computing optical
// depth"), blended back to front over the scene and cut by the scene's depth: the second step of
// the paper's algorithm overview, before any lighting (docs/clouds.md).
#include "clouds/optical_depth_table.hlsli"
#include "clouds/particle_shape.hlsli"

Texture3D<float> opticalDepthTable : register(t2);
Texture2D<float> sceneDepth : register(t3);
SamplerState linearWrapSampler : register(s0);

ShapeVertex vs_main(uint vertexId : SV_VertexID, uint instance : SV_InstanceID) { return shapeVertex(vertexId, instance); }

float4 ps_main(ShapeVertex input) : SV_Target {
    ParticlePixel px;
    if (!particlePixel(input, sceneDepth, frame.screen.zw, opticalDepthTable, linearWrapSampler, px)) discard;
    float3 white = frame.sunIrradiance.rgb * (0.8 / 3.14159265);
    return float4(white * px.opacity, px.opacity);
}
