// Test shader: transmittance exp(-tau) of an optical depth, times SCALE plus OFFSET, both
// given as defines, so that the build's define mechanism is tested along with the math.
StructuredBuffer<float> opticalDepth : register(t0);
RWStructuredBuffer<float> result : register(u0);

[numthreads(64, 1, 1)]
void main(uint3 global : SV_DispatchThreadID) {
    result[global.x] = exp(-opticalDepth[global.x]) * SCALE + OFFSET;
}
