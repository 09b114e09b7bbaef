// Cascaded shadow maps' geometry: the split formula, the bounding spheres, and stabilization
// (a world point moves by whole texels only while the camera moves and turns).
#include "shadows/CascadeSplits.h"

#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>

namespace firmament {
namespace {

TEST(CascadeSplits, BlendLogarithmicAndUniformPartitions) {
    const double n = 1.0, f = 100000.0;
    const auto uniform = cascadeSplits(n, f, 4, 0.0);
    const auto logarithmic = cascadeSplits(n, f, 4, 1.0);
    const auto blended = cascadeSplits(n, f, 4, 0.95);
    ASSERT_EQ(uniform.size(), 5u);
    for (int i = 0; i <= 4; ++i) {
        EXPECT_NEAR(uniform[i], n + (f - n) * i / 4.0, 1e-9 * f);
        EXPECT_NEAR(logarithmic[i], std::pow(10.0, 5.0 * i / 4.0), 1e-9 * f);  // 1, 17.8 m, 316 m, 5.6 km, 100 km
        EXPECT_NEAR(blended[i], 0.95 * logarithmic[i] + 0.05 * uniform[i], 1e-9 * f);
        if (i > 0) {
            EXPECT_GT(blended[i], blended[i - 1]);
        }
    }
    EXPECT_EQ(blended.front(), n);
    EXPECT_EQ(blended.back(), f);
    // Logarithmic splits keep a constant ratio from cascade to cascade.
    EXPECT_NEAR(logarithmic[2] / logarithmic[1], logarithmic[4] / logarithmic[3], 1e-9);
}

CascadeCamera cameraAt(glm::dvec3 position, double yaw, double pitch) {
    CascadeCamera c;
    c.position = position;
    c.forward = glm::dvec3(std::cos(pitch) * std::sin(yaw), std::sin(pitch), std::cos(pitch) * std::cos(yaw));
    c.tanHalfFovY = std::tan(3.141592653589793 / 8.0);  // 45 degrees
    c.aspectRatio = 16.0 / 9.0;
    return c;
}

// The eight corners of the slice [near, far] of the view frustum.
std::vector<glm::dvec3> sliceCorners(const CascadeCamera& c, double nearDepth, double farDepth) {
    const glm::dvec3 forward = glm::normalize(c.forward);
    const glm::dvec3 right = glm::normalize(glm::cross(glm::dvec3(0, 1, 0), forward));
    const glm::dvec3 up = glm::cross(forward, right);
    std::vector<glm::dvec3> corners;
    for (double z : {nearDepth, farDepth})
        for (double sx : {-1.0, 1.0})
            for (double sy : {-1.0, 1.0})
                corners.push_back(c.position + forward * z + right * (sx * z * c.tanHalfFovY * c.aspectRatio) + up * (sy * z * c.tanHalfFovY));
    return corners;
}

// The point lies inside the cascade's square and depth range.
void expectInsideTile(const Cascade& c, glm::dvec3 point) {
    const glm::dvec4 uvz = c.worldToShadow * glm::dvec4(point, 1.0);
    EXPECT_GE(uvz.x, 0.0);
    EXPECT_LE(uvz.x, 1.0);
    EXPECT_GE(uvz.y, 0.0);
    EXPECT_LE(uvz.y, 1.0);
    EXPECT_GT(uvz.z, 0.0);
    EXPECT_LT(uvz.z, 1.0);
}

TEST(CascadeSplits, SphereHoldsTheSliceAndKeepsItsSizeWhenTheCameraTurns) {
    const glm::dmat4 light = lightViewMatrix(glm::normalize(glm::dvec3(0.3, 0.5, 0.8)));
    const Cascade reference = fitCascade(cameraAt({0, 1000, 0}, 0.0, 0.0), 100.0, 2000.0, light, 1024, 1e5);
    for (int trial = 0; trial < 50; ++trial) {
        const CascadeCamera camera = cameraAt({trial * 311.7, 500.0 + trial * 13.0, -trial * 97.1}, trial * 0.37, std::sin(trial) * 1.2);
        const Cascade c = fitCascade(camera, 100.0, 2000.0, light, 1024, 1e5);
        EXPECT_DOUBLE_EQ(c.radius, reference.radius);
        for (const glm::dvec3& corner : sliceCorners(camera, 100.0, 2000.0)) {
            EXPECT_LE(glm::length(corner - c.centre), c.radius * (1.0 + 1e-12));
            // And the corner is inside the shadow map's square and depth range.
            expectInsideTile(c, corner);
        }
    }
}

// The light shafts' first marched cascade is fitted around the camera too: its sphere holds the
// camera's place and every slice of the frustum before its far split, and at the default
// partition (1 m to 100 km, four cascades, lambda 0.95) it grows little, since the far corners
// set its size.
TEST(CascadeSplits, TheCascadeAroundTheCameraHoldsTheWholePyramidAndGrowsLittle) {
    const glm::dmat4 light = lightViewMatrix(glm::normalize(glm::dvec3(0.3, 0.5, 0.8)));
    const std::vector<double> splits = cascadeSplits(1.0, 1.0e5, 4, 0.95);
    const CascadeCamera camera = cameraAt({120.0, 800.0, -40.0}, 0.7, -0.2);
    const Cascade own = fitCascade(camera, splits[1], splits[2], light, 1024, 1e5);
    const Cascade around = fitCascade(camera, splits[1], splits[2], light, 1024, 1e5, true);
    EXPECT_EQ(around.nearDepth, splits[1]);  // the range it shades is still its own
    EXPECT_GT(glm::length(camera.position - own.centre), own.radius) << "without the option the camera lies outside";
    std::vector<glm::dvec3> points = sliceCorners(camera, 0.5, splits[1]);
    points.push_back(camera.position);
    for (const glm::dvec3& p : points) expectInsideTile(around, p);
    const double growth = around.texelWorldSize / own.texelWorldSize - 1.0;
    std::printf("split 1 to 2 = %.0f to %.0f m: texel %.3f m, %.3f m around the camera (%.1f%% larger)\n", splits[1], splits[2],
                own.texelWorldSize, around.texelWorldSize, 100.0 * growth);
    EXPECT_GT(growth, 0.0);
    EXPECT_LT(growth, 0.02);
}

TEST(CascadeSplits, AWorldPointMovesByWholeTexelsOnlyUnderCameraMotion) {
    const int resolution = 2048;
    const glm::dmat4 light = lightViewMatrix(glm::normalize(glm::dvec3(-0.4, 0.35, 0.6)));
    const glm::dvec3 point(1234.5, 321.0, 4567.8);
    const Cascade first = fitCascade(cameraAt({1000, 800, 3000}, 0.2, -0.1), 50.0, 3000.0, light, resolution, 5e4);
    const glm::dvec4 reference = first.worldToShadow * glm::dvec4(point, 1.0);
    int moved = 0;
    for (int trial = 1; trial < 100; ++trial) {
        // Translations of arbitrary (not texel-multiple) lengths, and turns.
        const glm::dvec3 position(1000 + trial * 3.7131, 800 + trial * 0.913, 3000 - trial * 2.2917);
        const Cascade c = fitCascade(cameraAt(position, 0.2 + trial * 0.01, -0.1), 50.0, 3000.0, light, resolution, 5e4);
        const glm::dvec4 uvz = c.worldToShadow * glm::dvec4(point, 1.0);
        const glm::dvec2 texels = (glm::dvec2(uvz) - glm::dvec2(reference)) * static_cast<double>(resolution);
        EXPECT_NEAR(texels.x, std::round(texels.x), 1e-6) << "trial " << trial;
        EXPECT_NEAR(texels.y, std::round(texels.y), 1e-6) << "trial " << trial;
        if (std::round(texels.x) != 0.0 || std::round(texels.y) != 0.0) ++moved;
    }
    EXPECT_GT(moved, 50);  // the map did follow the camera
}

TEST(CascadeSplits, DepthGrowsAwayFromTheSun) {
    const glm::dvec3 toSun = glm::normalize(glm::dvec3(0.2, 0.7, -0.3));
    const Cascade c = fitCascade(cameraAt({0, 100, 0}, 0.0, 0.0), 1.0, 1000.0, lightViewMatrix(toSun), 1024, 1e4);
    const glm::dvec4 nearer = c.worldToShadow * glm::dvec4(c.centre + toSun * 100.0, 1.0);
    const glm::dvec4 farther = c.worldToShadow * glm::dvec4(c.centre - toSun * 100.0, 1.0);
    EXPECT_LT(nearer.z, farther.z);
    EXPECT_NEAR(nearer.x, farther.x, 1e-12);  // along the ray: the same texel
    EXPECT_NEAR(nearer.y, farther.y, 1e-12);
    // Casters up to casterReach towards the sun beyond the sphere stay in the depth range.
    EXPECT_GE((c.worldToShadow * glm::dvec4(c.centre + toSun * (c.radius + 1e4 - 1.0), 1.0)).z, 0.0);
}

}  // namespace
}  // namespace firmament
