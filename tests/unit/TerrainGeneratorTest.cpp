// The terrain's generator: deterministic, tileable, within its stated range; the height field's
// mip chain, slopes and bilinear sampling (the shaders' CPU twin); the surface's detail noise.
#include "terrain/HeightField.h"
#include "terrain/TerrainGenerator.h"
#include "terrain/TerrainSurface.h"
#include "core/Error.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstring>
#include <numeric>

namespace firmament {
namespace {

TerrainGeneratorParameters small() {
    TerrainGeneratorParameters p;
    p.size = 128;
    p.spacing = 256.0;  // the same 32.8 km tile, coarsely sampled
    return p;
}

std::uint64_t fnv1a(const std::vector<float>& values) {
    std::uint64_t hash = 0xcbf29ce484222325ull;
    const auto* bytes = reinterpret_cast<const unsigned char*>(values.data());
    for (size_t i = 0; i < values.size() * sizeof(float); ++i) hash = (hash ^ bytes[i]) * 0x100000001b3ull;
    return hash;
}

TEST(TerrainGenerator, SameParametersGiveBitIdenticalHeights) {
    const auto a = generateHeights(small());
    const auto b = generateHeights(small());
    ASSERT_EQ(a.size(), 128u * 128u);
    EXPECT_EQ(0, std::memcmp(a.data(), b.data(), a.size() * sizeof(float)));
    TerrainGeneratorParameters other = small();
    other.seed += 1;
    EXPECT_NE(fnv1a(a), fnv1a(generateHeights(other)));
}

// The heights of this build's generator, hashed: a change of the arithmetic (a compiler's
// contraction of a * b + c, another rounding) changes the terrain, and the cached files' key
// would no longer describe them. Update the hash only with a new generator version in describe().
TEST(TerrainGenerator, HeightsMatchTheRecordedHash) {
    EXPECT_EQ(fnv1a(generateHeights(small())), 0x9304e4ad78cb90d0ull) << std::hex << fnv1a(generateHeights(small()));
}

TEST(TerrainGenerator, LowestValleyIsAtSeaLevelAndPeaksWithinTheAmplitudes) {
    const TerrainGeneratorParameters p = small();
    const auto h = generateHeights(p);
    const auto [low, high] = std::minmax_element(h.begin(), h.end());
    EXPECT_EQ(*low, 0.0f);
    EXPECT_GT(*high, 0.4 * p.mountainHeight);  // there are mountains
    EXPECT_LT(*high, p.mountainHeight + p.hillHeight);
    const double mean = std::accumulate(h.begin(), h.end(), 0.0) / static_cast<double>(h.size());
    EXPECT_LT(mean, 0.5 * *high);  // and valleys between them
}

TEST(TerrainGenerator, GradientNoiseIsPeriodicZeroAtLatticePointsAndBounded) {
    for (int i = 0; i < 200; ++i) {
        const double x = 0.173 * i, z = 0.311 * i + 0.05;
        // Equal but for the rounding of the shifted coordinate's fraction.
        EXPECT_NEAR(gradientNoise(x, z, 8, 7u), gradientNoise(x + 8.0, z, 8, 7u), 1e-12);
        EXPECT_NEAR(gradientNoise(x, z, 8, 7u), gradientNoise(x, z - 16.0, 8, 7u), 1e-12);
        EXPECT_LE(std::abs(gradientNoise(x, z, 8, 7u)), 1.0 + 1e-12);
    }
    EXPECT_EQ(gradientNoise(3.0, 5.0, 8, 7u), 0.0);
}

TEST(TerrainGenerator, TheFieldTilesWithoutASeam) {
    // The step across the tile's edge is no larger than steps inside it.
    const TerrainGeneratorParameters p = small();
    const auto h = generateHeights(p);
    const int n = p.size;
    double largestInside = 0.0, largestAcross = 0.0;
    for (int j = 0; j < n; ++j) {
        for (int i = 0; i + 1 < n; ++i) largestInside = std::max(largestInside, std::abs(double(h[j * n + i + 1]) - h[j * n + i]));
        largestAcross = std::max(largestAcross, std::abs(double(h[j * n]) - h[j * n + n - 1]));
    }
    EXPECT_LE(largestAcross, largestInside);
}

HeightField sineField(int n, double spacing, double amplitude) {
    std::vector<float> h(static_cast<size_t>(n) * n);
    for (int j = 0; j < n; ++j)
        for (int i = 0; i < n; ++i) h[static_cast<size_t>(j) * n + i] = static_cast<float>(amplitude * std::sin(2.0 * 3.141592653589793 * i / n) + 0.5 * j);
    return HeightField(h, n, spacing);
}

TEST(HeightField, MipsAreBoxAveragesAndSamplingHitsTexelCentres) {
    std::vector<float> h(16 * 16);
    for (size_t k = 0; k < h.size(); ++k) h[k] = static_cast<float>((k * 37) % 101);
    const HeightField f(h, 16, 10.0);
    ASSERT_EQ(f.mipCount(), 5);
    EXPECT_FLOAT_EQ(f.heights(1)[0], (h[0] + h[1] + h[16] + h[17]) / 4.0f);
    EXPECT_FLOAT_EQ(f.heights(4)[0], static_cast<float>(std::accumulate(h.begin(), h.end(), 0.0) / 256.0));
    EXPECT_DOUBLE_EQ(f.sample(30.0, 50.0, 0), h[5 * 16 + 3]);  // sample (3, 5) stands at (30 m, 50 m)
    EXPECT_DOUBLE_EQ(f.sample(35.0, 50.0, 0), 0.5 * (h[5 * 16 + 3] + h[5 * 16 + 4]));
    EXPECT_DOUBLE_EQ(f.sample(30.0 + 160.0, 50.0 - 320.0, 0), f.sample(30.0, 50.0, 0));  // wraps
    // Mip 1's texel (0, 0) is centred between samples 0 and 1: x = z = 5 m.
    EXPECT_DOUBLE_EQ(f.sample(5.0, 5.0, 1), f.heights(1)[0]);
    EXPECT_THROW(HeightField(std::vector<float>(12 * 12), 12, 1.0), Error);
}

TEST(HeightField, SlopesAreCentralDifferences) {
    const HeightField f = sineField(64, 16.0, 100.0);
    const auto s = f.slopes(0);
    const double k = 2.0 * 3.141592653589793 / (64 * 16.0);
    for (int i = 0; i < 64; i += 5) {
        // Central difference of A sin(k x): A cos(k x) sin(k h) / h.
        const double expected = 100.0 * std::cos(k * i * 16.0) * std::sin(k * 16.0) / 16.0;
        EXPECT_NEAR(s[static_cast<size_t>(3 * 64 + i)].x, expected, 1e-4);
        EXPECT_NEAR(s[static_cast<size_t>(3 * 64 + i)].y, 0.5 / 16.0, 1e-6) << "the row ramp, except across the wrap";
    }
}

TEST(TerrainSurface, DetailNoiseFadesOnCoarseGridsAndStaysSmall) {
    double largest = 0.0;
    for (int i = 0; i < 500; ++i) {
        const double x = 13.7 * i - 3000.0, z = -7.3 * i + 1234.5;
        largest = std::max(largest, std::abs(detailHeight(x, z, 1.0)));
        EXPECT_EQ(detailHeight(x, z, kDetailLongestWavelength / 2.0), 0.0);  // no octave resolved
    }
    // The octaves' amplitudes sum to 6% of (64 + 32 + 16 + 8 + 4) m = 7.44 m.
    EXPECT_GT(largest, 1.0);
    EXPECT_LE(largest, kDetailAmplitude * 124.0);
}

TEST(TerrainSurface, MipChoiceAndEarthDrop) {
    const HeightField f = sineField(64, 16.0, 1.0);
    EXPECT_EQ(heightMipFor(1.0, f), 0);
    EXPECT_EQ(heightMipFor(16.0, f), 0);
    EXPECT_EQ(heightMipFor(32.0, f), 1);
    EXPECT_EQ(heightMipFor(1.0e6, f), f.mipCount() - 1);
    const double R = 6.36e6;
    EXPECT_DOUBLE_EQ(earthDrop(0.0, 0.0, R), 0.0);
    EXPECT_NEAR(earthDrop(100e3, 0.0, R), R - std::sqrt(R * R - 1e10), 1e-6);  // 786 m at 100 km
}

}  // namespace
}  // namespace firmament
