// The clipmap's layout: every level's edge falls on the next coarser level's vertices, each
// level's hole is exactly the finer level's square, and the index ranges cover each level's
// square less its hole once. Together these are what leaves no crack between levels (the
// vertex shader's morph does the rest; tests/app/TerrainCaptureTest.cpp looks at the frame).
#include "terrain/ClipmapLayout.h"
#include "terrain/ClipmapMesh.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <set>

namespace firmament {
namespace {

TEST(ClipmapLayout, LevelsNestOnTheCoarserGrid) {
    for (int trial = 0; trial < 200; ++trial) {
        const glm::dvec2 camera(std::fmod(trial * 7919.37, 100000.0) - 50000.0, std::fmod(trial * 104729.11, 80000.0) - 40000.0);
        const auto levels = clipmapLevels(camera, 0.0);
        ASSERT_EQ(levels.size(), static_cast<size_t>(kClipmapLevels));
        EXPECT_FALSE(levels[0].hasHole);
        for (size_t k = 0; k < levels.size(); ++k) {
            const ClipmapLevel& level = levels[k];
            EXPECT_EQ(level.spacing, std::ldexp(1.0, level.index));
            EXPECT_EQ(std::fmod(level.origin.x, 2.0 * level.spacing), 0.0);  // even indices are coarse vertices
            EXPECT_EQ(std::fmod(level.origin.y, 2.0 * level.spacing), 0.0);
            const glm::dvec2 centre = level.origin + level.spacing * (kClipmapCells / 2);
            EXPECT_LE(std::abs(centre.x - camera.x), level.spacing);  // the camera is near the middle
            EXPECT_LE(std::abs(centre.y - camera.y), level.spacing);
            if (k == 0) continue;
            const ClipmapLevel& finer = levels[k - 1];
            ASSERT_TRUE(level.hasHole);
            EXPECT_LE(std::abs(level.holeOffset.x), 1);
            EXPECT_LE(std::abs(level.holeOffset.y), 1);
            // The hole's corner is the finer level's origin, its width the finer level's.
            EXPECT_EQ(level.origin.x + holeFirstCell(level.holeOffset.x) * level.spacing, finer.origin.x);
            EXPECT_EQ(level.origin.y + holeFirstCell(level.holeOffset.y) * level.spacing, finer.origin.y);
            EXPECT_EQ((kClipmapCells / 2) * level.spacing, kClipmapCells * finer.spacing);
        }
    }
}

TEST(ClipmapLayout, HighCamerasSkipTheFinestLevels) {
    const auto low = clipmapLevels({0, 0}, 10.0);
    const auto high = clipmapLevels({0, 0}, 8000.0);
    EXPECT_EQ(low.front().index, 0);
    // The first level drawn reaches 2.5 times the height: half-width 32 * 2^L >= 20 km, L = 10.
    EXPECT_EQ(high.front().index, 10);
    EXPECT_FALSE(high.front().hasHole);
    EXPECT_EQ(high.back().index, kClipmapLevels - 1);
    // The coarsest level reaches beyond the horizon from 20 km up (505 km).
    EXPECT_GT((kClipmapCells / 2) * std::ldexp(kFinestSpacing, kClipmapLevels - 1), std::sqrt(2.0 * 6.36e6 * 20e3));
}

// Each cell of the grid, once per triangle pair, except the hole's.
TEST(ClipmapMesh, RangesCoverTheGridLessTheHoleOnce) {
    const ClipmapIndices mesh = buildClipmapIndices();
    constexpr int n = kClipmapCells;
    for (int variant = 0; variant < 10; ++variant) {
        const IndexRange range = mesh.ranges[static_cast<size_t>(variant)];
        std::multiset<int> cells;
        for (UINT t = 0; t < range.count; t += 3) {
            int column = n, row = n;  // the cell's lowest column and row
            for (int v = 0; v < 3; ++v) {
                const unsigned index = mesh.indices[range.first + t + static_cast<UINT>(v)];
                column = std::min(column, static_cast<int>(index % (n + 1)));
                row = std::min(row, static_cast<int>(index / (n + 1)));
            }
            cells.insert(column + n * row);
            // Clockwise seen from +y (x right, z up): a negative signed area in (x, z).
            const unsigned a = mesh.indices[range.first + t], b = mesh.indices[range.first + t + 1], c = mesh.indices[range.first + t + 2];
            const int ax = static_cast<int>(a % (n + 1)), az = static_cast<int>(a / (n + 1));
            const int bx = static_cast<int>(b % (n + 1)), bz = static_cast<int>(b / (n + 1));
            const int cx = static_cast<int>(c % (n + 1)), cz = static_cast<int>(c / (n + 1));
            EXPECT_LT((bx - ax) * (cz - az) - (bz - az) * (cx - ax), 0);
        }
        const bool holed = variant < 9;
        const int hx = holed ? holeFirstCell(variant / 3 - 1) : -1, hz = holed ? holeFirstCell(variant % 3 - 1) : -1;
        for (int j = 0; j < n; ++j)
            for (int i = 0; i < n; ++i) {
                const bool inHole = holed && i >= hx && i < hx + n / 2 && j >= hz && j < hz + n / 2;
                EXPECT_EQ(cells.count(i + n * j), inHole ? 0u : 2u) << "variant " << variant << " cell " << i << "," << j;
            }
    }
}

}  // namespace
}  // namespace firmament
