// Rasterization: a triangle over half the viewport, checked pixel by pixel against which
// pixel centres lie inside it, and the value each covered pixel wrote (its SV_Position).
#include "WarpDevice.h"
#include "gpu/Readback.h"
#include "gpu/Texture.h"

#include <cmath>

namespace firmament::test {
namespace {

TEST_F(WarpDevice, TriangleCoversExactlyThePixelCentresInsideIt) {
    constexpr int kSize = 64;
    const Texture2D target = createColorTexture(device(), kSize, kSize, DXGI_FORMAT_R32G32B32A32_FLOAT, D3D11_BIND_RENDER_TARGET);
    const float clear[4] = {-1.0f, -1.0f, -1.0f, -1.0f};
    context()->ClearRenderTargetView(target.rtv.Get(), clear);

    const D3D11_VIEWPORT viewport{0, 0, kSize, kSize, 0, 1};
    context()->OMSetRenderTargets(1, target.rtv.GetAddressOf(), nullptr);
    context()->RSSetViewports(1, &viewport);
    context()->IASetPrimitiveTopology(D3D11_PRIMITIVE_TOPOLOGY_TRIANGLELIST);
    context()->VSSetShader(testShaderLibrary->vertexShader({"draw/pixel_position.hlsl", "vs_main", "vs_5_0", {}}), nullptr, 0);
    context()->PSSetShader(testShaderLibrary->pixelShader({"draw/pixel_position.hlsl", "ps_main", "ps_5_0", {}}), nullptr, 0);
    context()->Draw(3, 0);

    const ReadbackImage image = readTexture2D(device(), context(), target.texture.Get());
    const auto texels = asVector<float>(image.bytes);
    int covered = 0, empty = 0;
    for (int y = 0; y < kSize; ++y)
        for (int x = 0; x < kSize; ++x) {
            const float* p = &texels[(static_cast<size_t>(y) * kSize + x) * 4];
            const double cx = x + 0.5, cy = y + 0.5;     // pixel centre
            const double edge = cx + cy - kSize;         // < 0 inside the triangle
            if (std::abs(edge) < 0.75) continue;         // on the diagonal: the fill rule decides
            if (edge < 0) {
                ++covered;
                ASSERT_EQ(p[0], cx) << x << "," << y;
                ASSERT_EQ(p[1], cy) << x << "," << y;
                ASSERT_NEAR(p[2], 0.5f, 1e-6f);
                ASSERT_EQ(p[3], 1.0f);
            } else {
                ++empty;
                ASSERT_EQ(p[0], -1.0f) << "pixel " << x << "," << y << " is outside the triangle";
            }
        }
    EXPECT_EQ(covered, empty);  // the diagonal splits the square evenly
    EXPECT_GT(covered, kSize * kSize / 3);
}

}  // namespace
}  // namespace firmament::test
