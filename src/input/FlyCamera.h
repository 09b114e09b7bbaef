#pragma once
// The fly camera: moves and turns the camera, and turns the sun, from one frame's input.
// Pure (no Windows calls), so its frame-rate independence is unit-tested.
#include "core/Camera.h"
#include "core/Settings.h"

#include <glm/vec2.hpp>
#include <glm/vec3.hpp>

namespace firmament {

struct FlightSettings {
    float speed = 200.0f;                  // metres per second at the ground, at full deflection
    float boost = 10.0f;                   // speed factor while Shift is held
    bool scaleWithAltitude = true;         // speed grows with altitude, to fly from the ground to space
    float mouseDegreesPerPixel = 0.15f;    // camera turn for a left-button drag
    float sunDegreesPerPixel = 0.2f;       // sun turn for a right-button drag
    float deviceDegreesPerSecond = 90.0f;  // turn rate of a stick or SpaceMouse at full deflection

    static constexpr Range<float> kSpeedRange{1.0f, 1.0e5f, true};
    static constexpr float kWheelStep = 1.25f;  // speed factor per mouse-wheel notch

    void visit(SettingsVisitor& v);  // section "flight"
};

// One frame's worth of input from every device, already mapped to camera terms.
struct FlightInput {
    glm::vec3 move{0.0f};          // x right, y up, z forward; each in -1..1
    bool boost = false;
    glm::vec2 turnDegrees{0.0f};   // yaw (right) and pitch (up), applied as they are (mouse)
    glm::vec2 turnRate{0.0f};      // yaw and pitch rates in -1..1 (sticks, SpaceMouse)
    glm::vec2 sunTurnDegrees{0.0f};  // azimuth and elevation
    int speedSteps = 0;            // mouse-wheel notches, positive faster

    FlightInput& operator+=(const FlightInput& other);
};

inline constexpr float kMinAltitude = 1.0f;         // metres above the ground plane
inline constexpr float kMaxAltitude = 1.0e6f;       // metres: 1000 km, well outside the atmosphere
inline constexpr float kAltitudeSpeedScale = 1000.0f;  // speed doubles every this many metres of altitude

// Speed factor at an altitude: 1 at the ground, 1 + altitude / 1 km above it.
float altitudeSpeedFactor(float altitude);

// Advances the camera and the sun by dtSeconds. Translation integrates the altitude-scaled
// speed exactly (an exponential in altitude when climbing), so the path does not depend on
// how the time is cut into frames.
void fly(Camera& camera, Sun& sun, FlightSettings& settings, const FlightInput& input, float dtSeconds);

}  // namespace firmament
