// The visibility pass (Yusov 2014, "Particle processing": a compute pass over the valid
// particles finds which are visible before they are drawn; docs/clouds.md, "Visibility"): the
// sorted keys of the particles whose bounding sphere is inside or crosses the view frustum, in
// their back-to-front order, and the instanced draw's arguments for them. One group walks the
// sorted keys in blocks of 256: each thread tests one particle against the six planes of the
// view-projection, and a scan over the block gives each visible key its place after those of the
// blocks before. The light-space tiling, the opacity and the shadow maps keep every particle: a
// particle outside the view still shades and shadows.
#include "clouds/cloud_sort.hlsli"

StructuredBuffer<uint2> sortedKeys : register(t1);
StructuredBuffer<CloudParticle> particles : register(t2);
RWStructuredBuffer<uint2> visibleKeys : register(u0);
// As the particles' arguments (list_arguments.hlsl): [3] the count, [4..7] DrawInstanced's.
RWBuffer<uint4> visibleArguments : register(u1);

static const uint kBlock = 256;
groupshared uint visibleBefore[kBlock];

// Whether the particle's bounding sphere reaches into the frustum: not wholly behind any of the
// planes clip.x = -w, w; clip.y = -w, w; clip.z = 0, w (clip = viewProjection x world, so plane k
// is a sum or difference of the matrix's rows). The margin keeps a sphere that only touches a
// plane, as the drawn quad, which covers the sphere's silhouette, would reach it.
bool inView(CloudParticle p) {
    float4x4 m = frame.viewProjection;
    float4 planes[6] = {m[3] + m[0], m[3] - m[0], m[3] + m[1], m[3] - m[1], m[2], m[3] - m[2]};
    float radius = max(p.centre.w, p.shape.x) * 1.01 + 1.0;
    float4 centre = float4(p.centre.xyz, 1.0);
    bool inside = true;
    [unroll] for (uint k = 0; k < 6; ++k) {
        float scale = length(planes[k].xyz);
        if (scale > 0.0 && dot(planes[k], centre) < -radius * scale) inside = false;
    }
    return inside;
}

[numthreads(256, 1, 1)]
void main(uint thread : SV_GroupIndex) {
    uint count = particleCount();
    uint written = 0;
    for (uint base = 0; base < count; base += kBlock) {
        uint index = base + thread;
        uint2 key = index < count ? sortedKeys[index] : uint2(0u, 0u);
        bool visible = index < count && inView(particles[key.y]);
        visibleBefore[thread] = visible ? 1u : 0u;
        GroupMemoryBarrierWithGroupSync();
        // An inclusive scan (Hillis and Steele): after it, entry t counts the visible keys 0..t.
        for (uint stride = 1; stride < kBlock; stride <<= 1) {
            uint add = thread >= stride ? visibleBefore[thread - stride] : 0u;
            GroupMemoryBarrierWithGroupSync();
            visibleBefore[thread] += add;
            GroupMemoryBarrierWithGroupSync();
        }
        if (visible) visibleKeys[written + visibleBefore[thread] - 1u] = key;
        written += visibleBefore[kBlock - 1];
        GroupMemoryBarrierWithGroupSync();
    }
    if (thread == 0) {
        visibleArguments[0] = uint4((written + 255u) / 256u, 0, 0, 0);
        visibleArguments[1] = uint4(1, 0, 0, 0);
        visibleArguments[2] = uint4(1, 0, 0, 0);
        visibleArguments[3] = uint4(written, 0, 0, 0);
        visibleArguments[4] = uint4(4, 0, 0, 0);
        visibleArguments[5] = uint4(written, 0, 0, 0);
        visibleArguments[6] = uint4(0, 0, 0, 0);
        visibleArguments[7] = uint4(0, 0, 0, 0);
    }
}
