// GPU timestamps: every frame is accounted for, and the numbers are consistent (a pass
// never takes longer than the frame around it).
#include "WarpDevice.h"
#include "gpu/GpuProfiler.h"
#include "gpu/Texture.h"

namespace firmament::test {
namespace {

TEST_F(WarpDevice, ProfilerTimesEveryPassOfEveryFrame) {
    const Texture2D target = createColorTexture(device(), 512, 512, DXGI_FORMAT_R16G16B16A16_FLOAT, D3D11_BIND_RENDER_TARGET);
    GpuProfiler profiler(device(), context());
    constexpr int kFrames = 10;  // more than the frames in flight: slots are reused
    const float colour[4] = {0.1f, 0.2f, 0.3f, 1.0f};
    for (int frame = 0; frame < kFrames; ++frame) {
        profiler.beginFrame();
        {
            auto pass = profiler.scope("Clear A");
            context()->ClearRenderTargetView(target.rtv.Get(), colour);
        }
        {
            auto pass = profiler.scope("Clear B");
            for (int i = 0; i < 4; ++i) context()->ClearRenderTargetView(target.rtv.Get(), colour);
        }
        profiler.endFrame();
    }
    profiler.flush();

    const auto& timings = profiler.timings();
    ASSERT_EQ(timings.size(), 3u);
    EXPECT_EQ(timings[0].name, "Frame");
    EXPECT_EQ(timings[1].name, "Clear A");
    EXPECT_EQ(timings[2].name, "Clear B");
    for (const PassTiming& t : timings) {
        EXPECT_EQ(t.frames + profiler.disjointFrames(), static_cast<std::uint64_t>(kFrames)) << t.name;
        EXPECT_GE(t.minMs, 0.0) << t.name;
        EXPECT_LE(t.minMs, t.meanMs) << t.name;
        EXPECT_LE(t.meanMs, t.maxMs) << t.name;
        EXPECT_LE(t.meanMs, timings[0].meanMs + 1e-9) << t.name << " longer than its frame";
    }
    EXPECT_LT(profiler.disjointFrames(), static_cast<std::uint64_t>(kFrames));
}

TEST_F(WarpDevice, ScopesOutsideAFrameAreIgnored) {
    GpuProfiler profiler(device(), context());
    { auto pass = profiler.scope("Stray"); }
    profiler.flush();
    ASSERT_EQ(profiler.timings().size(), 1u);  // only "Frame", never resolved
    EXPECT_EQ(profiler.timings()[0].frames, 0u);
}

}  // namespace
}  // namespace firmament::test
