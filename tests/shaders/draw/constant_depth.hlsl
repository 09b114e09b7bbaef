// Test shader: a full-screen triangle at one depth (the constant's x), for depth-only draws;
// and a copy of a depth texture's values, read through its shader resource view, into a float
// target (the way the program's passes read the camera's depth).
cbuffer Depth : register(b0) { float4 depth; };
Texture2D<float> depthTexture : register(t0);

float4 vs_main(uint vertexId : SV_VertexID) : SV_Position {
    const float2 corners[3] = { float2(-1.0, 1.0), float2(3.0, 1.0), float2(-1.0, -3.0) };
    return float4(corners[vertexId], depth.x, 1.0);
}

float4 ps_copy(float4 position : SV_Position) : SV_Target {
    return depthTexture.Load(int3(position.xy, 0)).xxxx;
}
