// Test shader: which mip level an implicit-derivative Sample reads. A full-screen triangle; row
// band b = floor(y / 8) scales the texture coordinates so that a pixel steps 2^(b * lodStep.x)
// texels of mip 0 along x and 2^(b * lodStep.y) along y, around an offset of `offset` whole
// tiles (wrap addressing). Each mip of the texture holds its own index, so the value read is the
// level of detail the sampler chose (fractional under trilinear filtering).
cbuffer Probe : register(b0) {
    float4 lodStep;  // x, y: log2 of the texel steps per band along x and y; z: texture side
    float4 offset;   // xy: whole tiles added to the coordinates
};
Texture2D<float2> mipIndex : register(t0);
SamplerState linearWrap : register(s0);

float4 vs_main(uint vertexId : SV_VertexID) : SV_Position {
    const float2 corners[3] = { float2(-1.0, 1.0), float2(3.0, 1.0), float2(-1.0, -3.0) };
    return float4(corners[vertexId], 0.5, 1.0);
}

float4 ps_main(float4 position : SV_Position) : SV_Target {
    float band = floor(position.y / 8.0);
    float2 texelsPerPixel = exp2(band * lodStep.xy);
    float2 uv = position.xy * texelsPerPixel / lodStep.z + offset.xy;
    float2 sampled = mipIndex.Sample(linearWrap, uv);
    return float4(sampled, band, 1.0);
}
