#pragma once
// Decoding of the HID input reports of the devices that fly the camera, as pure functions
// of the report bytes (hidapi hands them over with the report id first):
//  - 3Dconnexion SpaceMouse: the older format sends translation (report 1) and rotation
//    (report 2) separately; the newer one sends both in report 1 (13 bytes). Axes are signed
//    16-bit little-endian, about -350..350 at full deflection.
//  - Sony DualShock 4 and DualSense, USB report 1: sticks as bytes with 128 at rest, y down.
// Dead zones and the mapping to camera motion are here too.
#include "input/FlyCamera.h"

#include <cstdint>
#include <optional>
#include <span>
#include <string_view>

namespace firmament {

enum class HidDeviceKind { SpaceMouse, DualShock4, DualSense };

struct HidDeviceId {
    std::uint16_t vendor;
    std::uint16_t product;
};

std::optional<HidDeviceKind> hidDeviceKind(HidDeviceId id);  // nullopt: not a device we read
std::string_view hidDeviceKindName(HidDeviceKind kind);

struct SpaceMouseState {
    glm::ivec3 translation{0};  // raw counts: x right, y towards the person, z down
    glm::ivec3 rotation{0};     // raw counts about the same axes
    std::uint32_t buttons = 0;
};

// Updates `state` from one report; false when the report is not one of the formats above.
bool decodeSpaceMouseReport(std::span<const std::uint8_t> report, SpaceMouseState& state);

struct GamepadState {
    glm::vec2 leftStick{0.0f};   // -1..1, x right, y up
    glm::vec2 rightStick{0.0f};
    float leftTrigger = 0.0f;    // 0..1
    float rightTrigger = 0.0f;
    bool leftShoulder = false;
    bool rightShoulder = false;
};

std::optional<GamepadState> decodeDualShock4UsbReport(std::span<const std::uint8_t> report);
std::optional<GamepadState> decodeDualSenseUsbReport(std::span<const std::uint8_t> report);

// Scaled dead zone: values within `deadZone` of rest read 0, the rest is stretched back to
// the full range so motion starts smoothly at the edge of the zone.
float applyDeadZone(float value, float deadZone);
glm::vec2 applyRadialDeadZone(glm::vec2 stick, float deadZone);

struct DeviceSettings {
    bool enabled = true;                  // look for HID devices and XInput pads
    float stickDeadZone = 0.15f;          // fraction of the stick's travel
    float spaceMouseDeadZone = 0.05f;     // fraction of the SpaceMouse's travel

    void visit(SettingsVisitor& v);       // section "devices"
};

// Left stick moves (x strafe, y forward), right stick turns, triggers go down (left) and up
// (right), the right shoulder boosts.
FlightInput gamepadFlightInput(const GamepadState& pad, const DeviceSettings& settings);
// Push the cap to move, tilt and twist it to turn (pitch and yaw).
FlightInput spaceMouseFlightInput(const SpaceMouseState& state, const DeviceSettings& settings);

}  // namespace firmament
