// The terrain's generator: deterministic, tileable, within its stated range; the height field's
// mip chain, slopes and bilinear sampling (the shaders' CPU twin); the surface's detail noise.
#include "terrain/HeightField.h"
#include "terrain/TerrainGenerator.h"
#include "terrain/TerrainSurface.h"
#include "core/Error.h"

#include <glm/glm.hpp>

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
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
    EXPECT_EQ(fnv1a(generateHeights(small())), 0x3c8258a895996400ull) << std::hex << fnv1a(generateHeights(small()));
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

// LEAN mapping's second moment: mip 0 holds |s|^2, each coarser mip the box average, so that
// mip m's texel is the mean of |s|^2 over its 2^m x 2^m samples; at the 1 x 1 mip the mean slope
// is zero (the field wraps) and the moment is the whole field's slope variance.
TEST(HeightField, SlopeSecondMomentsAreBoxAveragesOfTheSquaredSlopes) {
    const HeightField f = sineField(64, 16.0, 100.0);
    const auto s = f.slopes(0);
    const auto moments = f.slopeSecondMoments();
    ASSERT_EQ(static_cast<int>(moments.size()), f.mipCount());
    const auto squared = [&](int i, int j) {
        const glm::dvec2 v(s[static_cast<size_t>(j * 64 + i)]);
        return glm::dot(v, v);
    };
    EXPECT_NEAR(moments[0][static_cast<size_t>(5 * 64 + 7)], squared(7, 5), 1e-6);
    // Mip 2's texel (1, 3) covers samples 4..7 along x and 12..15 along z.
    double box = 0.0;
    for (int j = 12; j < 16; ++j)
        for (int i = 4; i < 8; ++i) box += squared(i, j) / 16.0;
    EXPECT_NEAR(moments[2][static_cast<size_t>(3 * 16 + 1)], box, 1e-5);
    // The whole field: the sine's slopes have mean square (A k')^2 / 2 along x (k' the central
    // difference's k sin(k h) / (k h)), the ramp 0.5 / 16 along z but across the wrap.
    double all = 0.0;
    for (int j = 0; j < 64; ++j)
        for (int i = 0; i < 64; ++i) all += squared(i, j) / 4096.0;
    EXPECT_NEAR(moments.back()[0], all, 1e-5);
    const double k = 2.0 * 3.141592653589793 / (64 * 16.0);
    EXPECT_NEAR(all, 0.5 * std::pow(100.0 * std::sin(k * 16.0) / 16.0, 2.0) + std::pow(0.5 / 16.0, 2.0) * 62.0 / 64.0, 0.2 * all);
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

// The range mask: within [kPlainsRelief, 1]; the origin, where the program starts, on a range's
// flank (mountains within 15 km, the plain's edge too); over 1,000 km both ranges and plains;
// and no period of the height field's tile (32.8 km) nor of a few multiples of it, so the tile's
// repetition never shows as a lattice of ranges.
TEST(TerrainSurface, TheRangeMaskPlacesRangesAndPlainsWithoutRepeatingTheTile) {
    EXPECT_NEAR(rangeMask(0.0, 0.0), 0.42, 0.01);
    double highest = 0.0, lowest = 1.0;
    for (double x = -15000.0; x <= 15000.0; x += 5000.0)
        for (double z = -15000.0; z <= 15000.0; z += 5000.0) {
            highest = std::max(highest, rangeMask(x, z));
            lowest = std::min(lowest, rangeMask(x, z));
        }
    EXPECT_GT(highest, 0.95);
    EXPECT_LT(lowest, 0.3);
    int ranges = 0, plains = 0, samples = 0;
    double largestDifferenceOverATile[4] = {};
    for (int j = 0; j < 100; ++j)
        for (int i = 0; i < 100; ++i) {
            const double x = (i - 50) * 10000.0 + 1234.0, z = (j - 50) * 10000.0 - 777.0;
            const double m = rangeMask(x, z);
            EXPECT_GE(m, kPlainsRelief);
            EXPECT_LE(m, 1.0);
            ranges += m > 0.9;
            plains += m < kPlainsRelief + 0.05;
            ++samples;
            for (int t = 1; t <= 4; ++t)
                largestDifferenceOverATile[t - 1] = std::max(largestDifferenceOverATile[t - 1], std::abs(m - rangeMask(x + t * 32768.0, z)));
        }
    std::printf("ranges %.1f%%, plains %.1f%% of the samples\n", 100.0 * ranges / samples, 100.0 * plains / samples);
    EXPECT_GT(ranges, samples / 10);
    EXPECT_GT(plains, samples / 5);
    for (double d : largestDifferenceOverATile) EXPECT_GT(d, 0.5);
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
