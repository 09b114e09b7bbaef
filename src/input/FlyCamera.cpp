#include "input/FlyCamera.h"

#include <algorithm>
#include <cmath>

namespace firmament {

namespace {

float wrapDegrees(float angle) {
    angle = std::fmod(angle + 180.0f, 360.0f);
    if (angle < 0.0f) angle += 360.0f;
    return angle - 180.0f;
}

}  // namespace

void FlightSettings::visit(SettingsVisitor& v) {
    v.field("speed", speed, kSpeedRange, "Speed at the ground (m/s)");
    v.field("boost", boost, {1.0f, 100.0f}, "Shift speed factor");
    v.field("scaleWithAltitude", scaleWithAltitude, "Speed grows with altitude");
    v.field("mouseDegreesPerPixel", mouseDegreesPerPixel, {0.01f, 1.0f}, "Mouse turn (degrees/pixel)");
    v.field("sunDegreesPerPixel", sunDegreesPerPixel, {0.01f, 1.0f}, "Sun turn (degrees/pixel)");
    v.field("deviceDegreesPerSecond", deviceDegreesPerSecond, {5.0f, 360.0f}, "Device turn rate (degrees/s)");
}

FlightInput& FlightInput::operator+=(const FlightInput& other) {
    move = glm::clamp(move + other.move, glm::vec3(-1.0f), glm::vec3(1.0f));
    boost = boost || other.boost;
    turnDegrees += other.turnDegrees;
    turnRate = glm::clamp(turnRate + other.turnRate, glm::vec2(-1.0f), glm::vec2(1.0f));
    sunTurnDegrees += other.sunTurnDegrees;
    speedSteps += other.speedSteps;
    return *this;
}

float altitudeSpeedFactor(float altitude) { return 1.0f + std::max(altitude, 0.0f) / kAltitudeSpeedScale; }

void fly(Camera& camera, Sun& sun, FlightSettings& settings, const FlightInput& input, float dt) {
    if (input.speedSteps != 0)
        settings.speed = std::clamp(settings.speed * std::pow(FlightSettings::kWheelStep, static_cast<float>(input.speedSteps)),
                                    FlightSettings::kSpeedRange.min, FlightSettings::kSpeedRange.max);

    const glm::vec2 turn = input.turnDegrees + input.turnRate * settings.deviceDegreesPerSecond * dt;
    camera.yawDegrees = wrapDegrees(camera.yawDegrees + turn.x);
    camera.pitchDegrees = std::clamp(camera.pitchDegrees + turn.y, -Camera::kMaxPitchDegrees, Camera::kMaxPitchDegrees);
    sun.azimuthDegrees = wrapDegrees(sun.azimuthDegrees + input.sunTurnDegrees.x);
    sun.elevationDegrees = std::clamp(sun.elevationDegrees + input.sunTurnDegrees.y, -90.0f, 90.0f);

    const glm::vec3 move = camera.right() * input.move.x + glm::vec3(0.0f, input.move.y, 0.0f) + camera.forward() * input.move.z;
    const float deflection = std::min(glm::length(move), 1.0f);
    if (deflection <= 0.0f || dt <= 0.0f) return;
    const glm::vec3 direction = glm::normalize(move);
    const float groundSpeed = settings.speed * (input.boost ? settings.boost : 1.0f) * deflection;

    // Path length L over dt at speed v(h) = v0 (1 + h / H) with dh/dL = direction.y:
    // (H + h) grows as exp(v0 direction.y t / H), so L = (h(dt) - h0) / direction.y.
    const float h0 = std::max(camera.position.y, 0.0f);
    float pathLength = 0.0f;
    if (!settings.scaleWithAltitude) {
        pathLength = groundSpeed * dt;
    } else if (std::abs(direction.y) < 1e-6f) {
        pathLength = groundSpeed * altitudeSpeedFactor(h0) * dt;
    } else {
        const double H = kAltitudeSpeedScale;
        const double h1 = (H + h0) * std::exp(double(groundSpeed) * direction.y * dt / H) - H;
        pathLength = static_cast<float>((h1 - h0) / direction.y);
    }
    camera.position += direction * pathLength;
    camera.position.y = std::clamp(camera.position.y, kMinAltitude, kMaxAltitude);
}

}  // namespace firmament
