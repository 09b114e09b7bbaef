#include "input/HidReports.h"

#include <algorithm>
#include <array>
#include <cmath>

namespace firmament {

namespace {

constexpr float kSpaceMouseFullScale = 350.0f;

int int16At(std::span<const std::uint8_t> bytes, size_t offset) {
    return static_cast<std::int16_t>(static_cast<std::uint16_t>(bytes[offset] | bytes[offset + 1] << 8));
}

// A stick byte (0..255, 128 at rest) to -1..1.
float stickAxis(std::uint8_t value) { return std::clamp((static_cast<float>(value) - 128.0f) / 127.0f, -1.0f, 1.0f); }

struct ProductRange {
    std::uint16_t vendor;
    std::uint16_t product;
    HidDeviceKind kind;
};

constexpr std::array kKnownDevices{
    // 3Dconnexion under Logitech's vendor id (older devices, two-report format).
    ProductRange{0x046d, 0xc603, HidDeviceKind::SpaceMouse},  // SpaceMouse Plus XT
    ProductRange{0x046d, 0xc605, HidDeviceKind::SpaceMouse},  // CADman
    ProductRange{0x046d, 0xc606, HidDeviceKind::SpaceMouse},  // SpaceMouse Classic
    ProductRange{0x046d, 0xc621, HidDeviceKind::SpaceMouse},  // SpaceBall 5000
    ProductRange{0x046d, 0xc623, HidDeviceKind::SpaceMouse},  // SpaceTraveler
    ProductRange{0x046d, 0xc625, HidDeviceKind::SpaceMouse},  // SpacePilot
    ProductRange{0x046d, 0xc626, HidDeviceKind::SpaceMouse},  // SpaceNavigator
    ProductRange{0x046d, 0xc627, HidDeviceKind::SpaceMouse},  // SpaceExplorer
    ProductRange{0x046d, 0xc628, HidDeviceKind::SpaceMouse},  // SpaceNavigator for Notebooks
    ProductRange{0x046d, 0xc629, HidDeviceKind::SpaceMouse},  // SpacePilot Pro
    ProductRange{0x046d, 0xc62b, HidDeviceKind::SpaceMouse},  // SpaceMouse Pro
    // 3Dconnexion's own vendor id (newer devices, single-report format).
    ProductRange{0x256f, 0xc62e, HidDeviceKind::SpaceMouse},  // SpaceMouse Wireless (cable)
    ProductRange{0x256f, 0xc62f, HidDeviceKind::SpaceMouse},  // SpaceMouse Wireless (receiver)
    ProductRange{0x256f, 0xc631, HidDeviceKind::SpaceMouse},  // SpaceMouse Pro Wireless (cable)
    ProductRange{0x256f, 0xc632, HidDeviceKind::SpaceMouse},  // SpaceMouse Pro Wireless (receiver)
    ProductRange{0x256f, 0xc633, HidDeviceKind::SpaceMouse},  // SpaceMouse Enterprise
    ProductRange{0x256f, 0xc635, HidDeviceKind::SpaceMouse},  // SpaceMouse Compact
    ProductRange{0x256f, 0xc652, HidDeviceKind::SpaceMouse},  // Universal Receiver
    ProductRange{0x054c, 0x05c4, HidDeviceKind::DualShock4},
    ProductRange{0x054c, 0x09cc, HidDeviceKind::DualShock4},  // second revision
    ProductRange{0x054c, 0x0ba0, HidDeviceKind::DualShock4},  // USB wireless adaptor
    ProductRange{0x054c, 0x0ce6, HidDeviceKind::DualSense},
    ProductRange{0x054c, 0x0df2, HidDeviceKind::DualSense},   // DualSense Edge
};

}  // namespace

std::optional<HidDeviceKind> hidDeviceKind(HidDeviceId id) {
    for (const ProductRange& d : kKnownDevices)
        if (d.vendor == id.vendor && d.product == id.product) return d.kind;
    return std::nullopt;
}

std::string_view hidDeviceKindName(HidDeviceKind kind) {
    switch (kind) {
        case HidDeviceKind::SpaceMouse: return "3Dconnexion SpaceMouse";
        case HidDeviceKind::DualShock4: return "Sony DualShock 4";
        case HidDeviceKind::DualSense: return "Sony DualSense";
    }
    return "unknown";
}

bool decodeSpaceMouseReport(std::span<const std::uint8_t> report, SpaceMouseState& state) {
    if (report.empty()) return false;
    switch (report[0]) {
        case 1:
            if (report.size() >= 13) {  // newer format: translation and rotation together
                state.translation = {int16At(report, 1), int16At(report, 3), int16At(report, 5)};
                state.rotation = {int16At(report, 7), int16At(report, 9), int16At(report, 11)};
                return true;
            }
            if (report.size() >= 7) {  // older format: translation only
                state.translation = {int16At(report, 1), int16At(report, 3), int16At(report, 5)};
                return true;
            }
            return false;
        case 2:
            if (report.size() < 7) return false;
            state.rotation = {int16At(report, 1), int16At(report, 3), int16At(report, 5)};
            return true;
        case 3: {
            if (report.size() < 2) return false;
            std::uint32_t buttons = 0;
            for (size_t i = 1; i < std::min<size_t>(report.size(), 5); ++i) buttons |= std::uint32_t(report[i]) << (8 * (i - 1));
            state.buttons = buttons;
            return true;
        }
        default:
            return false;
    }
}

// DualShock 4, USB report 1: [1] LX [2] LY [3] RX [4] RY [5] hat and face buttons
// [6] L1 0x01, R1 0x02, L2 0x04, R2 0x08, ... [7] PS, touchpad, counter [8] L2 [9] R2.
std::optional<GamepadState> decodeDualShock4UsbReport(std::span<const std::uint8_t> report) {
    if (report.size() < 10 || report[0] != 0x01) return std::nullopt;
    GamepadState pad;
    pad.leftStick = {stickAxis(report[1]), -stickAxis(report[2])};
    pad.rightStick = {stickAxis(report[3]), -stickAxis(report[4])};
    pad.leftShoulder = report[6] & 0x01;
    pad.rightShoulder = report[6] & 0x02;
    pad.leftTrigger = report[8] / 255.0f;
    pad.rightTrigger = report[9] / 255.0f;
    return pad;
}

// DualSense, USB report 1: [1] LX [2] LY [3] RX [4] RY [5] L2 [6] R2 [7] counter
// [8] hat and face buttons [9] L1 0x01, R1 0x02, L2 0x04, R2 0x08, ... [10] PS, touchpad, mute.
std::optional<GamepadState> decodeDualSenseUsbReport(std::span<const std::uint8_t> report) {
    if (report.size() < 11 || report[0] != 0x01) return std::nullopt;
    GamepadState pad;
    pad.leftStick = {stickAxis(report[1]), -stickAxis(report[2])};
    pad.rightStick = {stickAxis(report[3]), -stickAxis(report[4])};
    pad.leftTrigger = report[5] / 255.0f;
    pad.rightTrigger = report[6] / 255.0f;
    pad.leftShoulder = report[9] & 0x01;
    pad.rightShoulder = report[9] & 0x02;
    return pad;
}

float applyDeadZone(float value, float deadZone) {
    const float magnitude = std::abs(value);
    if (magnitude <= deadZone) return 0.0f;
    return std::copysign(std::min((magnitude - deadZone) / (1.0f - deadZone), 1.0f), value);
}

glm::vec2 applyRadialDeadZone(glm::vec2 stick, float deadZone) {
    const float magnitude = glm::length(stick);
    if (magnitude <= deadZone) return glm::vec2(0.0f);
    return stick / magnitude * std::min((magnitude - deadZone) / (1.0f - deadZone), 1.0f);
}

void DeviceSettings::visit(SettingsVisitor& v) {
    v.field("enabled", enabled, "Use HID devices and game pads");
    v.field("stickDeadZone", stickDeadZone, {0.0f, 0.9f}, "Stick dead zone");
    v.field("spaceMouseDeadZone", spaceMouseDeadZone, {0.0f, 0.9f}, "SpaceMouse dead zone");
}

FlightInput gamepadFlightInput(const GamepadState& pad, const DeviceSettings& settings) {
    FlightInput in;
    const glm::vec2 move = applyRadialDeadZone(pad.leftStick, settings.stickDeadZone);
    const glm::vec2 turn = applyRadialDeadZone(pad.rightStick, settings.stickDeadZone);
    in.move = {move.x, applyDeadZone(pad.rightTrigger, settings.stickDeadZone) - applyDeadZone(pad.leftTrigger, settings.stickDeadZone),
               move.y};
    in.turnRate = turn;
    in.boost = pad.rightShoulder;
    return in;
}

FlightInput spaceMouseFlightInput(const SpaceMouseState& state, const DeviceSettings& settings) {
    auto axis = [&](int counts) {
        return applyDeadZone(std::clamp(static_cast<float>(counts) / kSpaceMouseFullScale, -1.0f, 1.0f), settings.spaceMouseDeadZone);
    };
    FlightInput in;
    // Device axes: x right, y towards the person, z down. Pushing the cap away flies forward,
    // lifting it flies up; tilting it back (about x) looks up, twisting it clockwise turns right.
    in.move = {axis(state.translation.x), -axis(state.translation.z), -axis(state.translation.y)};
    in.turnRate = {axis(state.rotation.z), -axis(state.rotation.x)};
    return in;
}

}  // namespace firmament
