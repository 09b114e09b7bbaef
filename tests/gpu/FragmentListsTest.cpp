// The exact fallback of volume-aware blending on the WARP device (src/clouds/VolumeBlendingPass,
// shaders/clouds/fragment_lists.hlsli and resolve_fragments.hlsl): synthetic stacks of 1 to 40
// overlapping fragments, appended to the per-pixel lists in random order, resolved over a
// background, against the CPU twin (blendVolumes); and the overflow of the pixel's limit and of
// the node pool counted.
#include "WarpDevice.h"
#include "clouds/VolumeBlendingPass.h"
#include "gpu/ConstantBuffer.h"
#include "gpu/Texture.h"
#include "reference/VolumeBlendingTwin.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <memory>
#include <random>

namespace firmament::test {
namespace {

struct SyntheticFragment {
    glm::vec4 colourExtinction;
    glm::vec2 extent;
    glm::uvec2 pixel;
};
static_assert(sizeof(SyntheticFragment) == 32, "matches append_fragments.hlsl");

const glm::vec3 kBackground(0.2f, 0.3f, 0.4f);

class FragmentListsTest : public WarpDevice {
protected:
    // Appends `fragments` to `pass`'s lists (begun for the target) and resolves them over the
    // background; returns the target's pixels.
    std::vector<glm::vec4> appendAndResolve(VolumeBlendingPass& pass, const Texture2D& target, const std::vector<SyntheticFragment>& fragments) {
        const float background[4] = {kBackground.x, kBackground.y, kBackground.z, 0.0f};
        context()->ClearRenderTargetView(target.rtv.Get(), background);
        // (An empty list appends nothing: a buffer cannot have no elements.)
        const std::vector<SyntheticFragment> appended = fragments.empty() ? std::vector<SyntheticFragment>(1) : fragments;
        auto input = structuredBuffer(appended, false);
        ComPtr<ID3D11ShaderResourceView> view;
        EXPECT_HRESULT_SUCCEEDED(device()->CreateShaderResourceView(input.Get(), nullptr, &view));
        ConstantBuffer<glm::uvec4> probe(device());
        probe.update(context(), glm::uvec4(static_cast<unsigned>(fragments.size()), pass.nodeCapacity(), 0u, static_cast<unsigned>(target.height)));
        context()->CSSetShader(testShaderLibrary->computeShader({"clouds/append_fragments.hlsl", "main", "cs_5_0", {}}), nullptr, 0);
        context()->CSSetShaderResources(0, 1, view.GetAddressOf());
        ID3D11Buffer* constants[] = {probe.get()};
        context()->CSSetConstantBuffers(0, 1, constants);
        pass.bindListsForCompute(context());
        context()->Dispatch(static_cast<UINT>((fragments.size() + 63) / 64), 1, 1);
        ID3D11UnorderedAccessView* none[2] = {};
        context()->CSSetUnorderedAccessViews(1, 2, none, nullptr);
        pass.resolve(context(), *productShaderLibrary, target.rtv.Get());
        return asVector<glm::vec4>(readTexture2D(device(), context(), target.texture.Get()).bytes);
    }

    // `draws` draws of `trianglesPerDraw` full-screen triangles of the test shader `file` over a
    // width x height target, `path` begun for it, probe (0, capacity, draw, height) at b0 and
    // `input` at t0; then the resolve. The pixels.
    std::vector<glm::vec4> drawAndResolve(ParticleBlending path, const char* file, int width, int height, unsigned draws, unsigned trianglesPerDraw = 1,
                                          ID3D11ShaderResourceView* input = nullptr) {
        const Texture2D target = createColorTexture(device(), width, height, DXGI_FORMAT_R32G32B32A32_FLOAT, D3D11_BIND_RENDER_TARGET);
        drawnPass = std::make_unique<VolumeBlendingPass>(device());
        drawnPass->begin(device(), context(), path, width, height);
        const float background[4] = {kBackground.x, kBackground.y, kBackground.z, 0.0f};
        context()->ClearRenderTargetView(target.rtv.Get(), background);
        ConstantBuffer<glm::uvec4> probe(device());
        const D3D11_VIEWPORT viewport{0.0f, 0.0f, static_cast<float>(width), static_cast<float>(height), 0.0f, 1.0f};
        context()->RSSetViewports(1, &viewport);
        context()->IASetPrimitiveTopology(D3D11_PRIMITIVE_TOPOLOGY_TRIANGLELIST);
        context()->VSSetShader(testShaderLibrary->vertexShader({file, "vs_main", "vs_5_0", {}}), nullptr, 0);
        context()->PSSetShader(testShaderLibrary->pixelShader({file, "ps_main", "ps_5_0", {}}), nullptr, 0);
        drawnPass->bindForParticles(context(), target.rtv.Get());
        context()->PSSetShaderResources(0, 1, &input);
        for (unsigned draw = 0; draw < draws; ++draw) {
            probe.update(context(), glm::uvec4(0u, drawnPass->nodeCapacity(), draw, static_cast<unsigned>(height)));
            ID3D11Buffer* constants[] = {probe.get()};
            context()->PSSetConstantBuffers(0, 1, constants);
            context()->Draw(3 * trianglesPerDraw, 0);
        }
        ID3D11ShaderResourceView* none = nullptr;
        context()->PSSetShaderResources(0, 1, &none);
        drawnPass->resolve(context(), *productShaderLibrary, target.rtv.Get());
        return asVector<glm::vec4>(readTexture2D(device(), context(), target.texture.Get()).bytes);
    }

    std::unique_ptr<VolumeBlendingPass> drawnPass;  // drawAndResolve's
};

// Overlapping fragments along one ray, in random order.
std::vector<ParticleFragment> randomStack(std::mt19937& random, int count) {
    std::uniform_real_distribution<float> unit(0.0f, 1.0f);
    std::vector<ParticleFragment> stack;
    for (int k = 0; k < count; ++k) {
        const float front = 100.0f + 900.0f * unit(random), length = 20.0f + 280.0f * unit(random);
        stack.push_back({{unit(random), unit(random), unit(random)}, 0.001f + 0.02f * unit(random), front, front + length});
    }
    return stack;
}

TEST_F(FragmentListsTest, TheResolvedPixelEqualsTheCpuTwinForStacksOfOneTo32AndReportsOverflow) {
    constexpr int kWidth = 40, kHeight = 4;
    const Texture2D target = createColorTexture(device(), kWidth, kHeight, DXGI_FORMAT_R32G32B32A32_FLOAT, D3D11_BIND_RENDER_TARGET);
    VolumeBlendingPass pass(device());
    pass.begin(device(), context(), ParticleBlending::PerPixelLists, kWidth, kHeight);
    ASSERT_EQ(pass.nodeCapacity(), kWidth * kHeight * VolumeBlendingPass::kNodesPerPixel);

    // Pixel k of row 1 holds k + 1 fragments (1..32); pixel 32 holds 40, eight past the limit.
    std::mt19937 random(17);
    std::vector<std::vector<ParticleFragment>> stacks;
    std::vector<SyntheticFragment> fragments;
    for (int k = 0; k <= 32; ++k) {
        stacks.push_back(randomStack(random, k < 32 ? k + 1 : 40));
        for (const ParticleFragment& f : stacks.back())
            fragments.push_back({glm::vec4(f.colour, f.extinction), glm::vec2(f.front, f.back), glm::uvec2(k, 1)});
    }
    std::shuffle(fragments.begin(), fragments.end(), random);
    const std::vector<glm::vec4> pixels = appendAndResolve(pass, target, fragments);

    for (int k = 0; k <= 32; ++k) {
        const BlendedLight expected = blendVolumes(stacks[k], 32);
        const glm::vec4 actual = pixels[kWidth + k];
        for (int c = 0; c < 3; ++c) {
            const float want = expected.light[c] + expected.transmittance * kBackground[c];
            EXPECT_NEAR(actual[c], want, 2e-4f + 1e-3f * want) << "pixel " << k << " channel " << c;
        }
        EXPECT_EQ(actual.a, 0.0f) << "the blending keeps the scene's alpha";
    }
    // Pixels without fragments keep the background.
    EXPECT_EQ(pixels[0], glm::vec4(kBackground, 0.0f));
    EXPECT_EQ(pixels[kWidth + 33], glm::vec4(kBackground, 0.0f));

    const VolumeBlendingPass::Overflow overflow = pass.readOverflow(device(), context());
    EXPECT_EQ(overflow.nodesAskedFor, fragments.size());
    EXPECT_EQ(overflow.nodesDropped, 0u);
    EXPECT_EQ(overflow.fragmentsDropped, 8u);
}

TEST_F(FragmentListsTest, APoolTooSmallDropsTheRestAndCountsThem) {
    constexpr int kWidth = 2, kHeight = 1;  // 64 nodes
    const Texture2D target = createColorTexture(device(), kWidth, kHeight, DXGI_FORMAT_R32G32B32A32_FLOAT, D3D11_BIND_RENDER_TARGET);
    VolumeBlendingPass pass(device());
    pass.begin(device(), context(), ParticleBlending::PerPixelLists, kWidth, kHeight);
    std::mt19937 random(4);
    std::vector<SyntheticFragment> fragments;
    for (const ParticleFragment& f : randomStack(random, 100))
        fragments.push_back({glm::vec4(f.colour, f.extinction), glm::vec2(f.front, f.back), glm::uvec2(1, 0)});
    const std::vector<glm::vec4> pixels = appendAndResolve(pass, target, fragments);
    const VolumeBlendingPass::Overflow overflow = pass.readOverflow(device(), context());
    ASSERT_EQ(pass.nodeCapacity(), 64u);
    EXPECT_EQ(overflow.nodesAskedFor, 100u);
    EXPECT_EQ(overflow.nodesDropped, 36u);
    EXPECT_EQ(overflow.fragmentsDropped, 32u);  // the 64 stored, in one pixel
    // The next frame's lists grow to 5/4 of what was asked (the counts are read late, never waiting;
    // the blocking read above has finished the copy).
    pass.begin(device(), context(), ParticleBlending::PerPixelLists, kWidth, kHeight);
    EXPECT_EQ(pass.nodeCapacity(), 125u);
    ASSERT_TRUE(pass.latestOverflow().has_value());
    EXPECT_EQ(pass.latestOverflow()->nodesDropped, 36u);
    const glm::vec4 covered = pixels[1];
    EXPECT_TRUE(std::isfinite(covered.r) && std::isfinite(covered.a));
    EXPECT_GT(glm::length(glm::vec3(covered) - kBackground), 0.1f);  // the fragments kept still cover the pixel
}

// The pixel stage appends as the particles' pass does (no render target, the views from u1):
// two overlapping fragments per pixel from two draws, resolved against the twin.
TEST_F(FragmentListsTest, FragmentsAppendedByThePixelStageResolveAsTheTwin) {
    constexpr int kWidth = 8, kHeight = 4;
    const std::vector<glm::vec4> pixels = drawAndResolve(ParticleBlending::PerPixelLists, "clouds/append_fragments.hlsl", kWidth, kHeight, 2);
    for (int y = 0; y < kHeight; ++y)
        for (int x = 0; x < kWidth; ++x) {
            std::vector<ParticleFragment> stack;
            for (int draw = 0; draw < 2; ++draw)
                stack.push_back({glm::vec3(x + 1, y + 1, draw + 1), 0.001f * (draw + 1), 100.0f + 10.0f * draw, 250.0f + 10.0f * draw});
            const BlendedLight expected = blendVolumes(stack, 32);
            for (int c = 0; c < 3; ++c) {
                const float want = expected.light[c] + expected.transmittance * kBackground[c];
                EXPECT_NEAR(pixels[y * kWidth + x][c], want, 1e-3f * want) << x << ", " << y << " channel " << c;
            }
        }
    EXPECT_EQ(drawnPass->readOverflow(device(), context()).nodesAskedFor, 2u * kWidth * kHeight);
}

// The rasterizer-ordered path's merge and resolve, with the order kept by one fragment per pixel
// per draw (Wine ignores the views' ordering; docs/clouds.md): four draws, a far fragment, one
// overlapping it, one wholly in front and one wholly behind, against the twin's VolumeBlend.
TEST_F(FragmentListsTest, TheOrderedPathMergesAndResolvesAsTheTwin) {
    constexpr int kWidth = 8, kHeight = 4;
    const std::vector<glm::vec4> pixels = drawAndResolve(ParticleBlending::RasterizerOrdered, "clouds/ordered_fragments.hlsl", kWidth, kHeight, 4);
    const float fronts[4] = {300.0f, 200.0f, 50.0f, 900.0f};
    for (int y = 0; y < kHeight; ++y)
        for (int x = 0; x < kWidth; ++x) {
            VolumeBlend twin;
            twin.behind.light = kBackground;
            for (int draw = 0; draw < 4; ++draw) twin.add({glm::vec3(x + 1, y + 1, draw + 1), 0.001f * (draw + 1), fronts[draw], fronts[draw] + 150.0f});
            const BlendedLight expected = twin.resolve();
            for (int c = 0; c < 3; ++c)
                EXPECT_NEAR(pixels[y * kWidth + x][c], expected.light[c], 1e-3f * expected.light[c]) << x << ", " << y << " channel " << c;
        }
}

// The ordered path as the particles use it: 24 overlapping fragments per pixel from one draw, in
// no back-to-front order, so that each pixel's result depends on the order they merge in, against
// the twin's VolumeBlend fed in primitive order. Only the views' ordering keeps that order within a
// draw, so the test runs only where the device has rasterizer-ordered views; elsewhere it is
// reported skipped, with the reason (it would test nothing, or test an order the API does not
// promise).
TEST_F(FragmentListsTest, ManyFragmentsPerPixelInOneDrawMergeInPrimitiveOrder) {
    const BlendingSupport support = queryBlendingSupport(device());
    if (!support.rasterizerOrderedViews || !support.typedUavLoads)
        GTEST_SKIP() << "not run: this device reports no rasterizer-ordered views (D3D11_FEATURE_D3D11_OPTIONS2: ROVsSupported "
                     << support.rasterizerOrderedViews << ", typed UAV loads " << support.typedUavLoads
                     << "), so nothing keeps primitive order within a draw";
    constexpr int kWidth = 8, kHeight = 4, kFragments = 24;
    std::mt19937 random(23);
    std::vector<ParticleFragment> stack = randomStack(random, kFragments);
    std::vector<SyntheticFragment> input;
    for (const ParticleFragment& f : stack) input.push_back({glm::vec4(f.colour, f.extinction), glm::vec2(f.front, f.back), glm::uvec2(0)});
    auto buffer = structuredBuffer(input, false);
    ComPtr<ID3D11ShaderResourceView> view;
    ASSERT_HRESULT_SUCCEEDED(device()->CreateShaderResourceView(buffer.Get(), nullptr, &view));
    const std::vector<glm::vec4> pixels =
        drawAndResolve(ParticleBlending::RasterizerOrdered, "clouds/ordered_fragments_one_draw.hlsl", kWidth, kHeight, 1, kFragments, view.Get());

    // The order matters for this stack: merged back to front, the light differs.
    VolumeBlend inOrder, backToFront;
    inOrder.behind.light = backToFront.behind.light = kBackground;
    for (const ParticleFragment& f : stack) inOrder.add(f);
    std::sort(stack.begin(), stack.end(), [](const ParticleFragment& a, const ParticleFragment& b) { return a.back > b.back; });
    for (const ParticleFragment& f : stack) backToFront.add(f);
    ASSERT_GT(glm::length(inOrder.resolve().light - backToFront.resolve().light), 0.01f) << "a stack whose order does not matter tests nothing";

    for (int y = 0; y < kHeight; ++y)
        for (int x = 0; x < kWidth; ++x) {
            VolumeBlend twin;
            twin.behind.light = kBackground;
            for (const SyntheticFragment& f : input) {
                const glm::vec3 colour = glm::vec3(f.colourExtinction) * glm::vec3(1.0f + 0.25f * x, 1.0f + 0.25f * y, 1.0f);
                twin.add({colour, f.colourExtinction.a, f.extent.x, f.extent.y});
            }
            const BlendedLight expected = twin.resolve();
            for (int c = 0; c < 3; ++c)
                EXPECT_NEAR(pixels[y * kWidth + x][c], expected.light[c], 1e-3f * expected.light[c] + 1e-5f) << x << ", " << y << " channel " << c;
        }
}

// The pixel shaders of every blending path are built (the ordered one with its rasterizer-ordered
// views, which no device here runs in order) and the device creates them.
TEST_F(FragmentListsTest, EveryPathsShadersAreBuiltAndCreated) {
    for (const char* model : {"CLOUD_ATMOSPHERE=1", "CLOUD_ATMOSPHERE=2", "CLOUD_ATMOSPHERE=3"})
        for (const char* path : {"CLOUD_BLENDING=0", "CLOUD_BLENDING=1", "CLOUD_BLENDING=2"})
            EXPECT_NE(productShaderLibrary->pixelShader({"clouds/shade_particles.hlsl", "ps_main", "ps_5_0", {model, path}}), nullptr) << model << " " << path;
    for (const char* resolve : {"clouds/resolve_fragments.hlsl", "clouds/resolve_ordered.hlsl"})
        EXPECT_NE(productShaderLibrary->pixelShader({resolve, "ps_main", "ps_5_0", {}}), nullptr) << resolve;
}

// Begun again, the lists start empty: nothing of the last frame is resolved twice.
TEST_F(FragmentListsTest, BeginningAgainEmptiesTheLists) {
    constexpr int kWidth = 4, kHeight = 2;
    const Texture2D target = createColorTexture(device(), kWidth, kHeight, DXGI_FORMAT_R32G32B32A32_FLOAT, D3D11_BIND_RENDER_TARGET);
    VolumeBlendingPass pass(device());
    pass.begin(device(), context(), ParticleBlending::PerPixelLists, kWidth, kHeight);
    std::mt19937 random(8);
    std::vector<SyntheticFragment> fragments;
    for (const ParticleFragment& f : randomStack(random, 3))
        fragments.push_back({glm::vec4(f.colour, f.extinction), glm::vec2(f.front, f.back), glm::uvec2(2, 0)});
    appendAndResolve(pass, target, fragments);
    pass.begin(device(), context(), ParticleBlending::PerPixelLists, kWidth, kHeight);
    const std::vector<glm::vec4> pixels = appendAndResolve(pass, target, {});
    EXPECT_EQ(pixels[2], glm::vec4(kBackground, 0.0f));
    EXPECT_EQ(pass.readOverflow(device(), context()).nodesAskedFor, 0u);
}

}  // namespace
}  // namespace firmament::test
