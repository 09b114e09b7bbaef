// The clipmap's layout: every level's edge falls on the next coarser level's vertices, each
// level's hole is exactly the finer level's square, and the index ranges cover each level's
// square less its hole once. Together these are what leaves no crack between levels (the
// vertex shader's morph does the rest; tests/app/TerrainCaptureTest.cpp looks at the frame).
#include "terrain/ClipmapLayout.h"
#include "terrain/ClipmapMesh.h"

#include <glm/geometric.hpp>
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <map>
#include <set>
#include <utility>
#include <vector>

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
    // The coarsest level reaches beyond the horizon from 1,000 km up (3,709 km), and its corners
    // stay inside the Earth's radius, where the surface's drop is defined.
    const double halfWidth = (kClipmapCells / 2) * std::ldexp(kFinestSpacing, kClipmapLevels - 1);
    EXPECT_GT(halfWidth, std::sqrt(2.0 * 6.371e6 * 1e6 + 1e6 * 1e6));
    EXPECT_LT(halfWidth * std::sqrt(2.0), 6.36e6);
}

// Each range covers its grid less the hole exactly once, with clockwise triangles, and is
// watertight: every edge inside the mesh is shared by exactly two triangles, and those used once
// lie on the grid's outer edge or the hole's. The cells along the hole take the midpoints of
// their hole-side edges, the finer level's boundary vertices: no T-junction is left.
TEST(ClipmapMesh, RangesCoverTheGridLessTheHoleOnceAndAreWatertight) {
    const ClipmapIndices mesh = buildClipmapIndices();
    constexpr int n = kClipmapCells, half = kClipmapCells / 2;
    for (int variant = 0; variant < 10; ++variant) {
        const bool holed = variant < 9;
        const glm::ivec2 hole = holed ? glm::ivec2(holeFirstCell(variant / 3 - 1), holeFirstCell(variant % 3 - 1)) : glm::ivec2(-100);
        const IndexRange range = mesh.ranges[static_cast<size_t>(variant)];
        std::vector<double> cellArea(static_cast<size_t>(n * n), 0.0);
        std::map<std::pair<unsigned, unsigned>, int> edges;
        int midpointsUsed = 0;
        for (UINT t = 0; t < range.count; t += 3) {
            unsigned ids[3];
            glm::dvec2 v[3];
            for (int k = 0; k < 3; ++k) {
                ids[k] = mesh.indices[range.first + t + static_cast<UINT>(k)];
                v[k] = clipmapVertexCell(ids[k], hole);
                if (ids[k] >= kClipmapGridVertices) ++midpointsUsed;
            }
            // Clockwise seen from +y (x right, z up): a negative signed area in (x, z).
            const double area = 0.5 * ((v[1].x - v[0].x) * (v[2].y - v[0].y) - (v[1].y - v[0].y) * (v[2].x - v[0].x));
            ASSERT_LT(area, 0.0) << "variant " << variant << " triangle " << t / 3;
            const glm::dvec2 centroid = (v[0] + v[1] + v[2]) / 3.0;
            cellArea[static_cast<size_t>(static_cast<int>(centroid.x) + n * static_cast<int>(centroid.y))] -= area;
            for (int k = 0; k < 3; ++k) ++edges[std::minmax(ids[k], ids[(k + 1) % 3])];
        }
        for (int j = 0; j < n; ++j)
            for (int i = 0; i < n; ++i) {
                const bool inHole = holed && i >= hole.x && i < hole.x + half && j >= hole.y && j < hole.y + half;
                EXPECT_NEAR(cellArea[static_cast<size_t>(i + n * j)], inHole ? 0.0 : 1.0, 1e-12) << "variant " << variant << " cell " << i << "," << j;
            }
        const auto onBoundary = [&](glm::dvec2 a, glm::dvec2 b) {
            const auto onLine = [&](double c, double line) { return c == line; };
            const bool outer = (onLine(a.x, 0) && onLine(b.x, 0)) || (onLine(a.x, n) && onLine(b.x, n)) || (onLine(a.y, 0) && onLine(b.y, 0)) ||
                               (onLine(a.y, n) && onLine(b.y, n));
            const bool inner = holed && ((onLine(a.x, hole.x) && onLine(b.x, hole.x)) || (onLine(a.x, hole.x + half) && onLine(b.x, hole.x + half)) ||
                                         (onLine(a.y, hole.y) && onLine(b.y, hole.y)) || (onLine(a.y, hole.y + half) && onLine(b.y, hole.y + half)));
            return outer || inner;
        };
        for (const auto& [edge, uses] : edges) {
            const glm::dvec2 a = clipmapVertexCell(edge.first, hole), b = clipmapVertexCell(edge.second, hole);
            EXPECT_LE(uses, 2) << "variant " << variant;
            if (uses == 1) {
                EXPECT_TRUE(onBoundary(a, b)) << "variant " << variant << ": an open edge inside the mesh (" << a.x << "," << a.y << ")-(" << b.x
                                              << "," << b.y << ")";
                if (holed && onBoundary(a, b) && glm::length(b - a) > 0.75 && a.x > 0 && a.x < n && a.y > 0 && a.y < n && b.x > 0 && b.x < n &&
                    b.y > 0 && b.y < n) {
                    ADD_FAILURE() << "variant " << variant << ": a whole cell edge on the hole, a T-junction against the finer level";
                }
            }
        }
        // Every midpoint, three triangles each.
        EXPECT_EQ(midpointsUsed, holed ? 3 * 4 * half : 0) << "variant " << variant;
    }
}

}  // namespace
}  // namespace firmament
