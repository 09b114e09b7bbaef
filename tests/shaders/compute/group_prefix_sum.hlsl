// Test shader: inclusive prefix sum within each 64-thread group (Hillis-Steele scan in
// group-shared memory). Exercises groupshared, barriers and structured buffers.
StructuredBuffer<uint> values : register(t0);
RWStructuredBuffer<uint> sums : register(u0);

groupshared uint partial[64];

[numthreads(64, 1, 1)]
void main(uint3 thread : SV_GroupThreadID, uint3 global : SV_DispatchThreadID) {
    partial[thread.x] = values[global.x];
    GroupMemoryBarrierWithGroupSync();
    [unroll]
    for (uint offset = 1; offset < 64; offset <<= 1) {
        uint before = thread.x >= offset ? partial[thread.x - offset] : 0;
        GroupMemoryBarrierWithGroupSync();
        partial[thread.x] += before;
        GroupMemoryBarrierWithGroupSync();
    }
    sums[global.x] = partial[thread.x];
}
