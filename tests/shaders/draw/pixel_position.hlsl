// Test shader: one triangle over the upper-left half of the viewport (clip-space vertices
// (-1,1), (1,1), (-1,-1)); every covered pixel writes its own SV_Position.
float4 vs_main(uint vertexId : SV_VertexID) : SV_Position {
    const float2 corners[3] = { float2(-1.0, 1.0), float2(1.0, 1.0), float2(-1.0, -1.0) };
    return float4(corners[vertexId], 0.5, 1.0);
}

float4 ps_main(float4 position : SV_Position) : SV_Target {
    return float4(position.xy, position.z, 1.0);
}
