// The fly camera: motion independent of the frame rate, speed scaling with altitude,
// turning, limits.
#include "input/FlyCamera.h"

#include <gtest/gtest.h>

#include <cmath>

namespace firmament {
namespace {

// Flies `seconds` cut into `frames` equal steps with the same input each frame.
Camera flyFor(float seconds, int frames, const FlightInput& input, FlightSettings settings = {}, Camera camera = {}) {
    Sun sun;
    for (int i = 0; i < frames; ++i) fly(camera, sun, settings, input, seconds / static_cast<float>(frames));
    return camera;
}

void expectSamePosition(const glm::vec3& a, const glm::vec3& b, float relative) {
    const float tolerance = relative * std::max(glm::length(a), 1.0f);
    EXPECT_NEAR(a.x, b.x, tolerance);
    EXPECT_NEAR(a.y, b.y, tolerance);
    EXPECT_NEAR(a.z, b.z, tolerance);
}

TEST(FlyCamera, HorizontalFlightCoversSpeedTimesAltitudeFactor) {
    FlightInput forward;
    forward.move.z = 1.0f;
    Camera start;  // 8000 m, looking along +z
    const Camera end = flyFor(2.0f, 120, forward, {}, start);
    const float expected = 200.0f * altitudeSpeedFactor(8000.0f) * 2.0f;  // 200 m/s * 9 * 2 s
    EXPECT_NEAR(end.position.z - start.position.z, expected, expected * 1e-5f);
    EXPECT_NEAR(end.position.y, start.position.y, 1e-3f);
}

TEST(FlyCamera, ClimbingDoesNotDependOnTheFrameRate) {
    FlightInput climb;
    climb.move = {0.3f, 1.0f, 0.7f};  // diagonal: forward, right and up
    climb.boost = true;
    Camera start;
    start.position.y = 50.0f;
    start.pitchDegrees = 20.0f;
    const Camera oneStep = flyFor(3.0f, 1, climb, {}, start);
    const Camera sixtyHz = flyFor(3.0f, 180, climb, {}, start);
    const Camera oddSteps = flyFor(3.0f, 37, climb, {}, start);
    expectSamePosition(oneStep.position, sixtyHz.position, 2e-5f);
    expectSamePosition(oneStep.position, oddSteps.position, 2e-5f);
    EXPECT_GT(oneStep.position.y, 50.0f + 3.0f * 2000.0f);  // boosted and scaled: far above the start
}

TEST(FlyCamera, DescendingStopsAtTheGround) {
    FlightInput down;
    down.move.y = -1.0f;
    Camera start;
    start.position.y = 100.0f;
    const Camera end = flyFor(60.0f, 60, down, {}, start);
    EXPECT_EQ(end.position.y, kMinAltitude);
}

TEST(FlyCamera, SpeedScalesWithAltitudeOnlyWhenAsked) {
    EXPECT_FLOAT_EQ(altitudeSpeedFactor(0.0f), 1.0f);
    EXPECT_FLOAT_EQ(altitudeSpeedFactor(100000.0f), 101.0f);
    FlightInput forward;
    forward.move.z = 1.0f;
    FlightSettings flat;
    flat.scaleWithAltitude = false;
    Camera start;
    const Camera end = flyFor(1.0f, 10, forward, flat, start);
    EXPECT_NEAR(end.position.z - start.position.z, 200.0f, 1e-2f);
}

TEST(FlyCamera, WheelChangesSpeedWithinItsRange) {
    FlightSettings settings;
    Camera camera;
    Sun sun;
    FlightInput wheel;
    wheel.speedSteps = 2;
    fly(camera, sun, settings, wheel, 0.0f);
    EXPECT_NEAR(settings.speed, 200.0f * 1.25f * 1.25f, 1e-3f);
    wheel.speedSteps = -1000;
    fly(camera, sun, settings, wheel, 0.0f);
    EXPECT_EQ(settings.speed, FlightSettings::kSpeedRange.min);
}

TEST(FlyCamera, TurnsCameraAndSunWithinLimits) {
    FlightSettings settings;
    Camera camera;
    Sun sun;
    FlightInput mouse;
    mouse.turnDegrees = {190.0f, 200.0f};
    mouse.sunTurnDegrees = {-200.0f, -150.0f};
    fly(camera, sun, settings, mouse, 1.0f / 60.0f);
    EXPECT_NEAR(camera.yawDegrees, -170.0f, 1e-4f);  // wrapped
    EXPECT_EQ(camera.pitchDegrees, Camera::kMaxPitchDegrees);
    EXPECT_NEAR(sun.azimuthDegrees, 160.0f, 1e-4f);
    EXPECT_EQ(sun.elevationDegrees, -90.0f);

    // A stick held at half deflection turns at half the device rate, whatever the frame rate.
    FlightInput stick;
    stick.turnRate = {0.5f, 0.0f};
    Camera a, b;
    Sun s;
    for (int i = 0; i < 60; ++i) fly(a, s, settings, stick, 1.0f / 60.0f);
    fly(b, s, settings, stick, 1.0f);
    EXPECT_NEAR(a.yawDegrees, 45.0f, 1e-3f);
    EXPECT_NEAR(b.yawDegrees, 45.0f, 1e-3f);
}

TEST(FlyCamera, InputsFromSeveralDevicesAddUpAndClamp) {
    FlightInput a, b;
    a.move = {1.0f, 0.0f, 0.5f};
    b.move = {1.0f, 0.0f, 0.25f};
    b.boost = true;
    b.speedSteps = 1;
    a += b;
    EXPECT_EQ(a.move, glm::vec3(1.0f, 0.0f, 0.75f));
    EXPECT_TRUE(a.boost);
    EXPECT_EQ(a.speedSteps, 1);
}

}  // namespace
}  // namespace firmament
