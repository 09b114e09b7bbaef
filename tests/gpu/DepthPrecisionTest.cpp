// How much precision a 32-bit float depth buffer keeps near 0, where reversed depth puts the
// far ground, and the atmosphere's passes take the distance to the ground from it. A depth-only
// draw at each of a range of small depths (1e-3 to 1e-10) is read back through a staging copy
// and through the shader resource view the passes use.
//   Direct3D 11 and DXVK store the float: a relative millionth.
//   Wine's wined3d loses a constant 1.3e-8 of absolute precision (what a round trip through
//   OpenGL's [-1, 1] depth range, 2z - 1 in float, would lose): 1.3% at 1e-6. The program fits
//   its near plane so that its depths stay large (core/Camera.h, withFittedNearPlane;
//   docs/building.md, "Two Direct3D 11 implementations"); this test measures the quirk, and
//   fails if wined3d loses more, or stops losing it (then the fitting's comment is stale).
#include "WarpDevice.h"
#include "gpu/CommonStates.h"
#include "gpu/ConstantBuffer.h"
#include "gpu/Readback.h"
#include "gpu/Texture.h"

#include <glm/glm.hpp>

#include <algorithm>
#include <cmath>
#include <vector>

namespace firmament::test {
namespace {

constexpr int kSide = 32;
constexpr int kBands = 8;  // rows of 4 pixels, each at one depth

float bandDepth(int band) { return 1e-3f * std::pow(0.1f, static_cast<float>(band)); }  // 1e-3 down to 1e-10

TEST_F(WarpDevice, SmallReversedDepthsKeepFloatPrecision) {
    const Texture2D depth = createDepthTexture(device(), kSide, kSide);
    context()->ClearDepthStencilView(depth.dsv.Get(), D3D11_CLEAR_DEPTH, 0.0f, 0);
    ConstantBuffer<glm::vec4> constants(device());
    D3D11_DEPTH_STENCIL_DESC writeAlways{};
    writeAlways.DepthEnable = TRUE;
    writeAlways.DepthWriteMask = D3D11_DEPTH_WRITE_MASK_ALL;
    writeAlways.DepthFunc = D3D11_COMPARISON_ALWAYS;
    ComPtr<ID3D11DepthStencilState> always;
    ASSERT_HRESULT_SUCCEEDED(device()->CreateDepthStencilState(&writeAlways, &always));
    ID3D11Buffer* buffer = constants.get();
    context()->OMSetRenderTargets(0, nullptr, depth.dsv.Get());
    context()->OMSetDepthStencilState(always.Get(), 0);
    context()->IASetPrimitiveTopology(D3D11_PRIMITIVE_TOPOLOGY_TRIANGLELIST);
    context()->VSSetShader(testShaderLibrary->vertexShader({"draw/constant_depth.hlsl", "vs_main", "vs_5_0", {}}), nullptr, 0);
    context()->VSSetConstantBuffers(0, 1, &buffer);
    context()->PSSetShader(nullptr, nullptr, 0);
    for (int band = 0; band < kBands; ++band) {
        constants.update(context(), glm::vec4(bandDepth(band), 0.0f, 0.0f, 0.0f));
        const float rows = static_cast<float>(kSide / kBands);
        const D3D11_VIEWPORT viewport{0, rows * static_cast<float>(band), kSide, rows, 0, 1};
        context()->RSSetViewports(1, &viewport);
        context()->Draw(3, 0);
    }

    // Through the shader resource view, as the passes read it.
    const Texture2D copy = createColorTexture(device(), kSide, kSide, DXGI_FORMAT_R32_FLOAT, D3D11_BIND_RENDER_TARGET);
    const D3D11_VIEWPORT full{0, 0, kSide, kSide, 0, 1};
    const auto none = states::depthNone(device());
    context()->OMSetRenderTargets(1, copy.rtv.GetAddressOf(), nullptr);
    context()->OMSetDepthStencilState(none.Get(), 0);
    context()->RSSetViewports(1, &full);
    context()->PSSetShader(testShaderLibrary->pixelShader({"draw/constant_depth.hlsl", "ps_copy", "ps_5_0", {}}), nullptr, 0);
    context()->PSSetShaderResources(0, 1, depth.srv.GetAddressOf());
    constants.update(context(), glm::vec4(0.5f, 0.0f, 0.0f, 0.0f));
    context()->Draw(3, 0);
    ID3D11ShaderResourceView* unbound = nullptr;
    context()->PSSetShaderResources(0, 1, &unbound);

    const auto staged = asVector<float>(readTexture2D(device(), context(), depth.texture.Get()).bytes);
    const auto viewed = asVector<float>(readTexture2D(device(), context(), copy.texture.Get()).bytes);
    const bool wined3d = gpu->implementation() == D3D11Implementation::Wined3d;
    double largestAbsoluteError = 0.0;
    for (int band = 0; band < kBands; ++band) {
        const size_t pixel = static_cast<size_t>(band * (kSide / kBands) + 1) * kSide + kSide / 2;
        const double expected = bandDepth(band);
        EXPECT_EQ(staged[pixel], viewed[pixel]) << "depth " << expected << ": the view and the staging copy disagree";
        const double error = std::abs(static_cast<double>(staged[pixel]) - expected);
        largestAbsoluteError = std::max(largestAbsoluteError, error);
        if (!wined3d) {
            EXPECT_LE(error / expected, 1e-6) << "depth " << expected << " came back as " << staged[pixel];
        } else {
            EXPECT_LE(error, 3e-8) << "depth " << expected << " came back as " << staged[pixel] << ": wined3d lost more than measured";
        }
    }
    std::printf("largest absolute depth error: %.3g\n", largestAbsoluteError);
    if (wined3d) {
        EXPECT_GT(largestAbsoluteError, 5e-9) << "wined3d keeps small depths now: the comments on the near plane's fitting are stale";
    }
}

}  // namespace
}  // namespace firmament::test
