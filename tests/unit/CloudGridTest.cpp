// The clouds' cell grid and cloud field on the CPU (src/clouds/CloudGrid.h, CloudField.h, src/reference/CloudFieldTwin.h): ring
// geometry, the rings tiling the outer square once, the grid moving in whole cells, the density
// map, and what the field model generates, against Yusov 2014's description of the grid.
#include "clouds/CloudField.h"
#include "clouds/CloudGrid.h"
#include "clouds/CloudSettings.h"
#include "reference/CloudFieldTwin.h"

#include <gtest/gtest.h>

#include <glm/geometric.hpp>

#include <cmath>
#include <map>
#include <set>
#include <vector>

namespace firmament {
namespace {

constexpr float kEarthRadius = 6360.0e3f;

std::vector<std::uint32_t> packedCells(const CloudGrid& grid) {
    std::vector<std::uint32_t> packed;
    for (const CloudCell& cell : grid.cells()) packed.push_back(packCloudCell(cell));
    return packed;
}

TEST(CloudGrid, EachRingsCellsAreTwiceTheInnerRingsAndTheOuterRingReachesTheParticleDistance) {
    for (int rings = 1; rings <= 8; ++rings)
        for (int dimension : {16, 128, 256}) {
            const CloudGrid grid(rings, dimension, 2.0e5);
            for (int r = 1; r < rings; ++r) EXPECT_DOUBLE_EQ(grid.cellSize(r), 2.0 * grid.cellSize(r - 1));
            EXPECT_DOUBLE_EQ(grid.cellSize(rings - 1) * dimension / 2.0, 2.0e5) << rings << " rings of " << dimension;
            EXPECT_EQ(static_cast<long long>(grid.cells().size()), CloudGrid::cellCount(rings, dimension));
        }
    // The sample's defaults: 128^2 + 4 x 3/4 x 128^2 cells, inner cells of 195.3 m.
    const CloudGrid defaults{CloudSettings{}};
    EXPECT_EQ(defaults.cells().size(), 65536u);
    EXPECT_NEAR(defaults.cellSize(0), 195.3125, 1e-9);
}

TEST(CloudGrid, TheRingsTileTheOuterSquareOnceWithoutGapsOrOverlaps) {
    for (int rings : {1, 2, 4}) {
        const int dimension = 16;
        const CloudGrid grid(rings, dimension, 1000.0);
        const int units = dimension << (rings - 1);  // ring 0's cells along the outer square
        const glm::dvec2 centre = grid.centre(glm::dvec2(123.0, -456.0));
        const double unit = grid.cellSize(0);
        std::vector<int> covered(static_cast<size_t>(units) * units, 0);
        for (const CloudCell& cell : grid.cells()) {
            const glm::dvec2 middle = grid.cellCentre(cell, centre);
            const double half = grid.cellSize(cell.ring) / 2.0;
            const int x0 = static_cast<int>(std::lround((middle.x - half - centre.x) / unit)) + units / 2;
            const int z0 = static_cast<int>(std::lround((middle.y - half - centre.y) / unit)) + units / 2;
            const int span = 1 << cell.ring;
            for (int z = z0; z < z0 + span; ++z)
                for (int x = x0; x < x0 + span; ++x) {
                    ASSERT_TRUE(x >= 0 && x < units && z >= 0 && z < units) << "a cell of ring " << cell.ring << " outside the square";
                    ++covered[static_cast<size_t>(z) * units + x];
                }
        }
        for (int c : covered) ASSERT_EQ(c, 1) << rings << " rings: a place covered " << c << " times";
    }
}

TEST(CloudGrid, TheGridMovesInWholeCellsSoThatCellsKeepTheirPlaceInTheWorld) {
    const CloudGrid grid(5, 32, 2.0e4);
    const double outer = grid.cellSize(4);
    for (const glm::dvec2 camera : {glm::dvec2(0.0, 0.0), glm::dvec2(3.7e3, -1.2e4), glm::dvec2(-9.87e5, 4.3e5)}) {
        const glm::dvec2 centre = grid.centre(camera);
        EXPECT_LE(std::abs(centre.x - camera.x), outer / 2.0 + 1e-6);
        EXPECT_LE(std::abs(centre.y - camera.y), outer / 2.0 + 1e-6);
        for (const CloudCell& cell : grid.cells()) {
            // Every cell's middle is at (k + 1/2) cells of its ring from the world's origin.
            const glm::dvec2 k = grid.cellCentre(cell, centre) / grid.cellSize(cell.ring) - 0.5;
            ASSERT_NEAR(k.x, std::round(k.x), 1e-6);
            ASSERT_NEAR(k.y, std::round(k.y), 1e-6);
        }
    }
    // A camera that moves less than half an outer cell from the snapped centre keeps the grid.
    EXPECT_EQ(grid.centre(glm::dvec2(0.49 * outer, -0.49 * outer)), grid.centre(glm::dvec2(0.0, 0.0)));
    EXPECT_EQ(grid.centre(glm::dvec2(0.51 * outer, 0.0)).x, outer);
}

TEST(CloudGrid, PackedCellsRoundTrip) {
    for (const CloudCell cell : {CloudCell{0, 0, 0}, CloudCell{7, 255, 1}, CloudCell{3, 17, 254}}) {
        const CloudCell back = unpackCloudCell(packCloudCell(cell));
        EXPECT_EQ(back.ring, cell.ring);
        EXPECT_EQ(back.i, cell.i);
        EXPECT_EQ(back.j, cell.j);
    }
}

TEST(CloudDensityMap, TexelsSpanZeroToOneAndTheMapTilesWithoutASeam) {
    for (int resolution : {128, 512}) {
        const std::vector<float> map = cloudDensityMap(resolution);
        float low = 1.0f, high = 0.0f;
        double neighbour = 0.0, seam = 0.0;
        for (int y = 0; y < resolution; ++y)
            for (int x = 0; x < resolution; ++x) {
                const float v = map[static_cast<size_t>(y) * resolution + x];
                low = std::min(low, v);
                high = std::max(high, v);
                if (x + 1 < resolution) neighbour += std::abs(map[static_cast<size_t>(y) * resolution + x + 1] - v);
            }
        for (int y = 0; y < resolution; ++y)
            seam += std::abs(map[static_cast<size_t>(y) * resolution] - map[static_cast<size_t>(y) * resolution + resolution - 1]);
        EXPECT_EQ(low, 0.0f);
        EXPECT_EQ(high, 1.0f);
        // Across the wrap the map changes as much as between any two neighbours.
        const double meanNeighbour = neighbour / (static_cast<double>(resolution - 1) * resolution), meanSeam = seam / resolution;
        EXPECT_LT(meanSeam, 2.0 * meanNeighbour) << resolution;
    }
}

struct FieldRun {
    CloudSettings settings;
    gpu::CloudFieldConstants constants;
    CloudFieldModel model;
};

FieldRun runField(CloudSettings settings, glm::dvec3 camera, double seconds) {
    FieldRun run{settings, cloudFieldConstants(settings, camera, seconds), {}};
    run.model = modelCloudField(run.constants, packedCells(CloudGrid(settings)), cloudDensityMap(settings.densityResolution), glm::vec3(camera),
                                kEarthRadius);
    return run;
}

TEST(CloudField, CloudinessSetsTheShareOfCoveredCells) {
    CloudSettings settings;
    settings.rings = 3;
    settings.ringDimension = 64;
    double previous = -1.0;
    for (float cloudiness : {0.0f, 0.2f, 0.4f, 0.65f, 0.8f, 1.0f}) {
        settings.cloudiness = cloudiness;
        const FieldRun run = runField(settings, glm::dvec3(0.0, 1500.0, 0.0), 0.0);
        double covered = 0.0;
        for (float c : run.model.coverage) covered += c > 0.0f ? 1.0 : 0.0;
        covered /= static_cast<double>(run.model.coverage.size());
        if (cloudiness == 0.0f) {
            EXPECT_EQ(covered, 0.0);
            EXPECT_TRUE(run.model.particles.empty());
        } else {
            // Within 0.1 of the control in the middle of its range, rising with it.
            if (cloudiness >= 0.4f && cloudiness <= 0.8f) {
                EXPECT_NEAR(covered, cloudiness, 0.1);
            }
            EXPECT_GT(covered, previous) << cloudiness;
        }
        previous = covered;
    }
}

TEST(CloudField, LayersFillFromTheBottomWithinTheLayerAndTheParticleDistance) {
    CloudSettings settings;
    settings.rings = 4;
    settings.ringDimension = 64;
    settings.particleDistance = 5.0e4f;
    const glm::dvec3 camera(2.0e4, 2500.0, -7.0e3);
    const FieldRun run = runField(settings, camera, 42.0);
    ASSERT_GT(run.model.particles.size(), 1000u);
    std::map<unsigned, std::set<int>> layersOfCell;
    for (const ModelParticle& p : run.model.particles) {
        layersOfCell[p.cell].insert(p.layer);
        EXPECT_LE(glm::length(glm::dvec3(p.centre) - camera) - p.horizontalRadius, settings.particleDistance + 1e-3);
        // Its altitude above the sphere: within the layer, give or take a layer's jitter.
        const double altitude = glm::length(glm::dvec3(p.centre) + glm::dvec3(0.0, kEarthRadius, 0.0)) - kEarthRadius;
        EXPECT_GT(altitude, settings.altitude - settings.thickness / 2.0 - 1.0);
        EXPECT_LT(altitude, settings.altitude + settings.thickness / 2.0 + 1.0);
        EXPECT_GT(p.horizontalRadius, 0.0f);
        EXPECT_LE(p.verticalRadius, p.horizontalRadius);
        EXPECT_GT(p.density, 0.0f);
        EXPECT_LE(p.density, 1.0f);
    }
    const CloudGrid grid(settings);
    for (const auto& [cell, layers] : layersOfCell) {
        // Layers 0..n-1 and nothing above, where the particle distance cuts none off.
        const double size = grid.cellSize(grid.cells()[cell].ring);
        if (run.model.reach[cell] + 3.0 * size + settings.thickness > settings.particleDistance) continue;
        int expected = 0;
        for (int layer : layers) {
            if (layer != expected) ADD_FAILURE() << "cell " << cell << ": layer " << layer << " without layer " << expected;
            expected = layer + 1;
        }
    }
}

TEST(CloudField, ParticlesKeepTheirPlaceWhileTheCameraMovesAndPulseWithTime) {
    CloudSettings settings;
    settings.rings = 2;
    settings.ringDimension = 32;
    settings.particleDistance = 2.0e4f;
    settings.speed = 0.0f;
    const FieldRun a = runField(settings, glm::dvec3(0.0, 1500.0, 0.0), 10.0);
    const FieldRun b = runField(settings, glm::dvec3(1.9e3, 1500.0, 800.0), 10.0);  // past an outer cell (1250 m)
    ASSERT_NE(a.constants.centre.x, b.constants.centre.x);
    auto key = [](const ModelParticle& p) { return std::make_tuple(std::lround(p.centre.x * 4.0f), std::lround(p.centre.z * 4.0f), p.layer); };
    std::map<std::tuple<long, long, int>, ModelParticle> before;
    for (const ModelParticle& p : a.model.particles) before[key(p)] = p;
    int shared = 0;
    for (const ModelParticle& p : b.model.particles) {
        const auto found = before.find(key(p));
        if (found == before.end()) continue;
        ++shared;
        EXPECT_NEAR(found->second.horizontalRadius, p.horizontalRadius, 1e-3f);
        EXPECT_NEAR(found->second.density, p.density, 1e-6f);
    }
    // Most of the field is the same particles, in the same places.
    EXPECT_GT(shared, static_cast<int>(a.model.particles.size()) / 2);
    // Time changes the particles' sizes and densities, not their places (a few at the particle
    // distance come and go with their size).
    const FieldRun later = runField(settings, glm::dvec3(0.0, 1500.0, 0.0), 17.0);
    std::map<std::pair<unsigned, int>, ModelParticle> earlier;
    for (const ModelParticle& p : a.model.particles) earlier[{p.cell, p.layer}] = p;
    int changed = 0, same = 0;
    for (const ModelParticle& p : later.model.particles) {
        const auto found = earlier.find({p.cell, p.layer});
        if (found == earlier.end()) continue;
        ++same;
        EXPECT_EQ(p.centre, found->second.centre);
        changed += p.horizontalRadius != found->second.horizontalRadius && p.density != found->second.density;
    }
    EXPECT_GT(same, static_cast<int>(a.model.particles.size()) * 99 / 100);
    EXPECT_GT(changed, same * 9 / 10);
}

TEST(CloudField, TheWindMovesThePattern) {
    CloudSettings settings;
    settings.rings = 2;
    settings.ringDimension = 32;
    settings.particleDistance = 2.0e4f;
    const FieldRun still = runField(settings, glm::dvec3(0.0, 1500.0, 0.0), 0.0);
    // After 100 s at speed 0.2 (10 m/s) the coverage at a place equals that 1 km upwind before.
    const FieldRun moved = runField(settings, glm::dvec3(0.0, 1500.0, 0.0), 100.0);
    EXPECT_NE(still.model.coverage, moved.model.coverage);
    EXPECT_NEAR(moved.constants.wind.x, 800.0f, 1e-2f);
    EXPECT_NEAR(moved.constants.wind.y, 600.0f, 1e-2f);
}

}  // namespace
}  // namespace firmament
