// For tests/gpu/EpipolarSamplingTest.cpp: a synthetic depth buffer, written through SV_Depth by
// a full-screen triangle: sky (depth 0) above the row profile.y, and below it a ground whose
// reversed-Z depth is `near` and `far` in alternating vertical bands of profile.x pixels, so
// that every slice crosses depth breaks at places the test knows.
cbuffer ProfileBuffer : register(b0) {
    float4 profile;  // x: band width (pixels); y: the horizon's row; z: near depth; w: far depth
};

struct Vertex {
    float4 position : SV_Position;
};

Vertex vs_main(uint vertexId : SV_VertexID) {
    float2 uv = float2((vertexId << 1) & 2, vertexId & 2);
    Vertex v;
    v.position = float4(uv * float2(2.0, -2.0) + float2(-1.0, 1.0), 0.0, 1.0);
    return v;
}

float ps_main(Vertex input) : SV_Depth {
    float2 pixel = floor(input.position.xy);
    if (pixel.y < profile.y) return 0.0;
    return fmod(floor(pixel.x / profile.x), 2.0) == 0.0 ? profile.z : profile.w;
}
