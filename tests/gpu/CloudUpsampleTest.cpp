// The clouds' low-resolution rendering on the WARP device (src/clouds/LowResolution,
// shaders/clouds/downsample_depth.hlsl and upsample_clouds.hlsl): the low-resolution depth is each
// block's nearest; across a depth edge (terrain against sky) at every alignment to the blocks, the
// bilateral upsample gives each full-resolution pixel the clouds of its own side, except at most
// within one pixel of the edge; at 1x it is the identity.
#include "WarpDevice.h"
#include "clouds/LowResolution.h"
#include "gpu/Texture.h"

#include <gtest/gtest.h>

#include <glm/gtc/packing.hpp>

#include <cmath>
#include <cstdint>
#include <random>

namespace firmament::test {
namespace {

constexpr int kWidth = 32, kHeight = 8;
const glm::vec3 kBackground(0.0f, 0.0f, 1.0f);
constexpr float kTerrainDepth = 0.02f;  // reversed depth: 0 is the sky

class CloudUpsampleTest : public WarpDevice {
protected:
    Texture2D depthTexture(const std::vector<float>& depths, int width, int height) {
        Texture2D t = createColorTexture(device(), width, height, DXGI_FORMAT_R32_FLOAT, D3D11_BIND_SHADER_RESOURCE);
        context()->UpdateSubresource(t.texture.Get(), 0, nullptr, depths.data(), width * 4, 0);
        return t;
    }
    // Writes `texels` (premultiplied light, transmittance) into the low-resolution clouds.
    void fillClouds(const CloudLowResolution& low, const std::vector<glm::vec4>& texels) {
        std::vector<std::uint16_t> halves;
        for (const glm::vec4& t : texels)
            for (int c = 0; c < 4; ++c) halves.push_back(glm::packHalf1x16(t[c]));
        context()->UpdateSubresource(low.clouds().texture.Get(), 0, nullptr, halves.data(), low.clouds().width * 8, 0);
    }
    std::vector<glm::vec4> upsample(CloudLowResolution& low, const Texture2D& depth, int width, int height) {
        const Texture2D target = createColorTexture(device(), width, height, DXGI_FORMAT_R32G32B32A32_FLOAT, D3D11_BIND_RENDER_TARGET);
        const float background[4] = {kBackground.x, kBackground.y, kBackground.z, 0.0f};
        context()->ClearRenderTargetView(target.rtv.Get(), background);
        low.upsample(context(), *productShaderLibrary, depth.srv.Get(), target.rtv.Get(), width, height);
        return asVector<glm::vec4>(readTexture2D(device(), context(), target.texture.Get()).bytes);
    }
};

TEST_F(CloudUpsampleTest, ADepthEdgeStaysWithinOnePixelAtEveryAlignment) {
    const glm::vec4 overTerrain(0.8f, 0.1f, 0.0f, 0.5f), overSky(0.1f, 0.7f, 0.0f, 0.25f);
    for (int factor : {2, 4})
        for (int edge = 8; edge < 12; ++edge) {
            // Terrain left of the edge column, sky from it on.
            std::vector<float> depths(kWidth * kHeight);
            for (int y = 0; y < kHeight; ++y)
                for (int x = 0; x < kWidth; ++x) depths[y * kWidth + x] = x < edge ? kTerrainDepth : 0.0f;
            const Texture2D depth = depthTexture(depths, kWidth, kHeight);
            CloudLowResolution low(device());
            low.begin(device(), context(), *productShaderLibrary, depth.srv.Get(), kWidth, kHeight, factor);
            ASSERT_EQ(low.clouds().width, kWidth / factor);
            // The low-resolution depth: the block's nearest, so terrain wherever the block holds any.
            const std::vector<float> lowDepth = asVector<float>(readTexture2D(device(), context(), low.depth().texture.Get()).bytes);
            std::vector<glm::vec4> clouds;
            for (int y = 0; y < kHeight / factor; ++y)
                for (int x = 0; x < kWidth / factor; ++x) {
                    const float expected = x * factor < edge ? kTerrainDepth : 0.0f;
                    EXPECT_EQ(lowDepth[y * (kWidth / factor) + x], expected) << "factor " << factor << " edge " << edge << " block " << x;
                    clouds.push_back(expected > 0.0f ? overTerrain : overSky);
                }
            fillClouds(low, clouds);
            const std::vector<glm::vec4> frame = upsample(low, depth, kWidth, kHeight);
            int wrong = 0;
            for (int y = 0; y < kHeight; ++y)
                for (int x = 0; x < kWidth; ++x) {
                    const glm::vec4 side = x < edge ? overTerrain : overSky;
                    const glm::vec3 want = glm::vec3(side) + side.a * kBackground;
                    const bool right = glm::length(glm::vec3(frame[y * kWidth + x]) - want) < 0.02f;
                    if (right) continue;
                    ++wrong;
                    EXPECT_LE(std::abs(x - edge + 0.5), 1.0) << "factor " << factor << ", edge at " << edge << ": pixel " << x << " takes the other side";
                }
            EXPECT_LE(wrong, kHeight) << "factor " << factor << " edge " << edge;  // at most one column
        }
}

TEST_F(CloudUpsampleTest, AtOneXTheUpsampleIsTheIdentity) {
    std::mt19937 random(12);
    std::uniform_real_distribution<float> unit(0.0f, 1.0f);
    std::vector<float> depths(kWidth * kHeight);
    for (float& d : depths) d = unit(random) < 0.3f ? 0.0f : 0.001f + 0.1f * unit(random);
    const Texture2D depth = depthTexture(depths, kWidth, kHeight);
    CloudLowResolution low(device());
    low.begin(device(), context(), *productShaderLibrary, depth.srv.Get(), kWidth, kHeight, 1);
    std::vector<glm::vec4> clouds(kWidth * kHeight);
    for (glm::vec4& c : clouds) c = glm::vec4(unit(random), unit(random), unit(random), unit(random));
    fillClouds(low, clouds);
    const std::vector<glm::vec4> frame = upsample(low, depth, kWidth, kHeight);
    for (int i = 0; i < kWidth * kHeight; ++i) {
        const glm::vec4 c = glm::unpackHalf4x16(glm::packHalf4x16(clouds[i]));
        const glm::vec3 want = glm::vec3(c) + c.a * kBackground;
        for (int k = 0; k < 3; ++k) EXPECT_NEAR(frame[i][k], want[k], 1e-6f) << "pixel " << i;
    }
}

}  // namespace
}  // namespace firmament::test
