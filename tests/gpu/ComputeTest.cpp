// Compute shaders on the device against the same computation on the CPU.
#include "WarpDevice.h"
#include "gpu/Readback.h"

#include <cmath>
#include <random>

namespace firmament::test {
namespace {

TEST_F(WarpDevice, GroupPrefixSumMatchesTheCpu) {
    constexpr size_t kGroups = 16, kCount = kGroups * 64;
    std::mt19937 random(11);
    std::vector<std::uint32_t> values(kCount);
    for (auto& v : values) v = random() % 1000;

    auto input = structuredBuffer(values, false);
    auto output = structuredBuffer(std::vector<std::uint32_t>(kCount, 0xdeadbeef), true);
    ComPtr<ID3D11ShaderResourceView> srv;
    ComPtr<ID3D11UnorderedAccessView> uav;
    ASSERT_HRESULT_SUCCEEDED(device()->CreateShaderResourceView(input.Get(), nullptr, &srv));
    ASSERT_HRESULT_SUCCEEDED(device()->CreateUnorderedAccessView(output.Get(), nullptr, &uav));

    context()->CSSetShader(testShaderLibrary->computeShader({"compute/group_prefix_sum.hlsl", "main", "cs_5_0", {}}), nullptr, 0);
    context()->CSSetShaderResources(0, 1, srv.GetAddressOf());
    context()->CSSetUnorderedAccessViews(0, 1, uav.GetAddressOf(), nullptr);
    context()->Dispatch(kGroups, 1, 1);

    const auto sums = asVector<std::uint32_t>(readBuffer(device(), context(), output.Get()));
    ASSERT_EQ(sums.size(), kCount);
    for (size_t group = 0; group < kGroups; ++group) {
        std::uint32_t running = 0;
        for (size_t i = group * 64; i < (group + 1) * 64; ++i) {
            running += values[i];
            ASSERT_EQ(sums[i], running) << "element " << i;
        }
    }
}

TEST_F(WarpDevice, TransmittanceWithDefinesMatchesTheCpu) {
    constexpr size_t kCount = 256;
    std::vector<float> opticalDepth(kCount);
    for (size_t i = 0; i < kCount; ++i) opticalDepth[i] = static_cast<float>(i) * 0.05f;  // 0 .. 12.75

    auto input = structuredBuffer(opticalDepth, false);
    auto output = structuredBuffer(std::vector<float>(kCount, -1.0f), true);
    ComPtr<ID3D11ShaderResourceView> srv;
    ComPtr<ID3D11UnorderedAccessView> uav;
    ASSERT_HRESULT_SUCCEEDED(device()->CreateShaderResourceView(input.Get(), nullptr, &srv));
    ASSERT_HRESULT_SUCCEEDED(device()->CreateUnorderedAccessView(output.Get(), nullptr, &uav));

    // Defines given out of order: the key sorts them as the build did.
    const ShaderKey key{"compute/transmittance.hlsl", "main", "cs_5_0", {"SCALE=3.0", "OFFSET=0.5"}};
    context()->CSSetShader(testShaderLibrary->computeShader(key), nullptr, 0);
    context()->CSSetShaderResources(0, 1, srv.GetAddressOf());
    context()->CSSetUnorderedAccessViews(0, 1, uav.GetAddressOf(), nullptr);
    context()->Dispatch(kCount / 64, 1, 1);

    const auto result = asVector<float>(readBuffer(device(), context(), output.Get()));
    for (size_t i = 0; i < kCount; ++i) {
        const double expected = std::exp(-static_cast<double>(opticalDepth[i])) * 3.0 + 0.5;
        ASSERT_NEAR(result[i], expected, 2e-6 * expected) << "optical depth " << opticalDepth[i];
    }
}

}  // namespace
}  // namespace firmament::test
