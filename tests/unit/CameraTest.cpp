// Camera matrices against Direct3D's conventions: left-handed, reversed Z (depth 1 at near, 0 at far).
#include "core/Camera.h"

#include <gtest/gtest.h>

#include <cmath>

namespace firmament {
namespace {

glm::vec3 project(const glm::mat4& m, glm::vec3 p) {
    const glm::vec4 clip = m * glm::vec4(p, 1.0f);
    return glm::vec3(clip) / clip.w;
}

// Reversed Z: the near plane at depth 1, the far plane at 0.
TEST(Camera, NearAndFarPlanesMapToDepthOneAndZero) {
    Camera camera;
    camera.position = {0.0f, 0.0f, 0.0f};
    camera.nearPlane = 0.5f;
    camera.farPlane = 1000.0f;
    const glm::mat4 viewProjection = camera.projection(16.0f / 9.0f) * camera.view();
    EXPECT_NEAR(project(viewProjection, {0, 0, 0.5f}).z, 1.0f, 1e-6f);
    EXPECT_NEAR(project(viewProjection, {0, 0, 1000.0f}).z, 0.0f, 1e-6f);
    // Depth falls with distance, as n / z for a far plane much farther than the near one.
    EXPECT_GT(project(viewProjection, {0, 0, 10.0f}).z, project(viewProjection, {0, 0, 20.0f}).z);
    EXPECT_NEAR(project(viewProjection, {0, 0, 50.0f}).z, 0.5f / 50.0f * (1000.0f - 50.0f) / (1000.0f - 0.5f), 1e-6f);
}

// The near plane fitted below the highest surface: 1 m on the ground, half the clearance above
// it. From 400 km up, the horizon's ground (2300 km away) then lands at a depth of about 0.09,
// where wined3d's constant 1.3e-8 of depth error (tests/gpu/DepthPrecisionTest.cpp) is a relative
// 2e-7; with a 1 m plane it landed near 3e-7, and the error was 4%.
TEST(Camera, NearPlaneFitsBelowTheHighestSurface) {
    Camera camera;
    camera.position = {0.0f, 2.0f, 0.0f};
    EXPECT_EQ(withFittedNearPlane(camera, 5000.0).nearPlane, 1.0f);  // below the peaks: the camera's own plane
    camera.position.y = 10000.0f;
    EXPECT_EQ(withFittedNearPlane(camera, 5000.0).nearPlane, 2500.0f);
    camera.position.y = 400000.0f;
    camera.pitchDegrees = -20.0f;  // the horizon, seen from 400 km, is 20 degrees below level
    const Camera fitted = withFittedNearPlane(camera, 5000.0);
    EXPECT_EQ(fitted.nearPlane, 197500.0f);
    const glm::vec3 horizon = camera.position + 2.3e6f * camera.forward();
    const float depth = project(fitted.projection(16.0f / 9.0f) * fitted.view(), horizon).z;
    EXPECT_NEAR(depth, 197500.0 / 2.3e6 * (1e7 - 2.3e6) / (1e7 - 197500.0), 1e-5);  // n / z (f - z) / (f - n)
    EXPECT_LT(1.3e-8 / depth, 2e-7);
    EXPECT_LT(project(camera.projection(16.0f / 9.0f) * camera.view(), horizon).z, 1e-6f);  // the 1 m plane's depth there
}

TEST(Camera, VerticalFieldOfViewReachesTheTopEdge) {
    Camera camera;
    camera.position = {0.0f, 0.0f, 0.0f};
    const float halfFov = glm::radians(camera.verticalFovDegrees) * 0.5f;
    const glm::mat4 viewProjection = camera.projection(2.0f) * camera.view();
    // A point at the top edge of the view frustum at distance 10 lands at clip-space y = 1.
    EXPECT_NEAR(project(viewProjection, {0.0f, 10.0f * std::tan(halfFov), 10.0f}).y, 1.0f, 1e-5f);
    // x is right (left-handed): a point to the right has positive x.
    EXPECT_GT(project(viewProjection, {1.0f, 0.0f, 10.0f}).x, 0.0f);
}

TEST(Camera, YawAndPitchTurnTheForwardVector) {
    Camera camera;
    camera.yawDegrees = 90.0f;  // looks along +x; right is then -z
    EXPECT_NEAR(camera.forward().x, 1.0f, 1e-6f);
    EXPECT_NEAR(camera.right().z, -1.0f, 1e-6f);
    camera.pitchDegrees = 30.0f;
    EXPECT_NEAR(camera.forward().y, 0.5f, 1e-6f);
    EXPECT_NEAR(glm::length(camera.forward()), 1.0f, 1e-6f);
    EXPECT_NEAR(glm::dot(camera.forward(), camera.right()), 0.0f, 1e-6f);
}

TEST(Camera, SunDirectionFromElevationAndAzimuth) {
    const glm::vec3 zenith = directionFromElevationAzimuth(1.5707963f, 0.0f);
    EXPECT_NEAR(zenith.y, 1.0f, 1e-6f);
    const glm::vec3 east = directionFromElevationAzimuth(0.0f, 1.5707963f);
    EXPECT_NEAR(east.x, 1.0f, 1e-6f);
    EXPECT_NEAR(east.y, 0.0f, 1e-6f);
    Sun sun;
    sun.elevationDegrees = 30.0f;
    sun.azimuthDegrees = -90.0f;
    EXPECT_NEAR(sun.direction().y, 0.5f, 1e-6f);
    EXPECT_NEAR(sun.direction().x, -std::cos(glm::radians(30.0f)), 1e-6f);
}

}  // namespace
}  // namespace firmament
