// Compute shaders on the device against the same computation on the CPU.
#include "WarpDevice.h"

#include <cmath>
#include <random>

namespace firmament::test {
namespace {

TEST_F(WarpDevice, GroupPrefixSumMatchesTheCpu) {
    constexpr size_t kGroups = 16, kCount = kGroups * 64;
    std::mt19937 random(11);
    std::vector<std::uint32_t> values(kCount);
    for (auto& v : values) v = random() % 1000;

    const auto sums = runCompute(ShaderKey{"compute/group_prefix_sum.hlsl", "main", "cs_5_0", {}}, values, kCount,
                                 std::uint32_t{0xdeadbeef}, kGroups);
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

    // Defines given out of order: the key sorts them as the build did.
    const ShaderKey key{"compute/transmittance.hlsl", "main", "cs_5_0", {"SCALE=3.0", "OFFSET=0.5"}};
    const auto result = runCompute(key, opticalDepth, kCount, -1.0f, kCount / 64);
    ASSERT_EQ(result.size(), kCount);
    for (size_t i = 0; i < kCount; ++i) {
        const double expected = std::exp(-static_cast<double>(opticalDepth[i])) * 3.0 + 0.5;
        ASSERT_NEAR(result[i], expected, 2e-6 * expected) << "optical depth " << opticalDepth[i];
    }
}

}  // namespace
}  // namespace firmament::test
