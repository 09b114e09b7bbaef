// Hot-reload test shader: a full-screen triangle in the colour that reload/color.hlsli
// defines. The test edits that include and checks what is drawn.
#include "reload/color.hlsli"

float4 vs_main(uint vertexId : SV_VertexID) : SV_Position {
    float2 uv = float2((vertexId << 1) & 2, vertexId & 2);
    return float4(uv * float2(2.0, -2.0) + float2(-1.0, 1.0), 0.0, 1.0);
}

float4 ps_main() : SV_Target {
    return float4(RELOAD_COLOR, 1.0);
}
