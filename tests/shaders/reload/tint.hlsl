// A second shader of the "reload" technique: a reload replaces both or neither.
float4 ps_main() : SV_Target {
    return float4(0.0, 0.0, 1.0, 1.0);
}
