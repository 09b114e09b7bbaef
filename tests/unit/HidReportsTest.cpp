// HID report decoding with report bytes as the devices send them (report id first, as
// hidapi returns them), dead zones, and the mapping to camera motion.
#include "input/HidReports.h"

#include <gtest/gtest.h>

#include <array>
#include <vector>

namespace firmament {
namespace {

TEST(HidReports, KnownDevicesByVendorAndProduct) {
    EXPECT_EQ(hidDeviceKind({0x046d, 0xc626}), HidDeviceKind::SpaceMouse);  // SpaceNavigator
    EXPECT_EQ(hidDeviceKind({0x256f, 0xc635}), HidDeviceKind::SpaceMouse);  // SpaceMouse Compact
    EXPECT_EQ(hidDeviceKind({0x054c, 0x09cc}), HidDeviceKind::DualShock4);
    EXPECT_EQ(hidDeviceKind({0x054c, 0x0ce6}), HidDeviceKind::DualSense);
    EXPECT_FALSE(hidDeviceKind({0x046d, 0xc077}).has_value());  // a Logitech mouse
}

TEST(HidReports, SpaceMouseOlderFormatSendsTranslationAndRotationApart) {
    SpaceMouseState state;
    // Report 1: x = 350 (0x015e), y = -2 (0xfffe), z = -350 (0xfea2).
    const std::vector<std::uint8_t> translation{0x01, 0x5e, 0x01, 0xfe, 0xff, 0xa2, 0xfe};
    ASSERT_TRUE(decodeSpaceMouseReport(translation, state));
    EXPECT_EQ(state.translation, glm::ivec3(350, -2, -350));
    EXPECT_EQ(state.rotation, glm::ivec3(0));
    // Report 2: rotation x = 100, y = 0, z = -175.
    const std::vector<std::uint8_t> rotation{0x02, 0x64, 0x00, 0x00, 0x00, 0x51, 0xff};
    ASSERT_TRUE(decodeSpaceMouseReport(rotation, state));
    EXPECT_EQ(state.rotation, glm::ivec3(100, 0, -175));
    EXPECT_EQ(state.translation, glm::ivec3(350, -2, -350));  // kept from report 1
    // Report 3: buttons.
    ASSERT_TRUE(decodeSpaceMouseReport(std::vector<std::uint8_t>{0x03, 0x03, 0x00}, state));
    EXPECT_EQ(state.buttons, 3u);
}

TEST(HidReports, SpaceMouseNewerFormatSendsAllSixAxesInReportOne) {
    SpaceMouseState state;
    const std::vector<std::uint8_t> report{0x01, 0x0a, 0x00, 0xf6, 0xff, 0x00, 0x00, 0x2c, 0x01, 0xd4, 0xfe, 0x01, 0x00};
    ASSERT_TRUE(decodeSpaceMouseReport(report, state));
    EXPECT_EQ(state.translation, glm::ivec3(10, -10, 0));
    EXPECT_EQ(state.rotation, glm::ivec3(300, -300, 1));
    EXPECT_FALSE(decodeSpaceMouseReport(std::vector<std::uint8_t>{0x01, 0x00}, state));   // truncated
    EXPECT_FALSE(decodeSpaceMouseReport(std::vector<std::uint8_t>{0x17, 0x00, 0x00}, state));  // other report
}

TEST(HidReports, DualShock4UsbReport) {
    std::array<std::uint8_t, 64> report{};
    // Left stick full right and full up, right stick at rest, hat neutral (8), R1 held,
    // R2 fully pressed.
    const std::uint8_t head[] = {0x01, 0xff, 0x00, 0x80, 0x80, 0x08, 0x02, 0x00, 0x00, 0xff};
    std::copy(std::begin(head), std::end(head), report.begin());
    const auto pad = decodeDualShock4UsbReport(report);
    ASSERT_TRUE(pad.has_value());
    EXPECT_FLOAT_EQ(pad->leftStick.x, 1.0f);
    EXPECT_FLOAT_EQ(pad->leftStick.y, 1.0f);  // y up
    EXPECT_FLOAT_EQ(pad->rightStick.x, 0.0f);
    EXPECT_TRUE(pad->rightShoulder);
    EXPECT_FALSE(pad->leftShoulder);
    EXPECT_FLOAT_EQ(pad->rightTrigger, 1.0f);
    EXPECT_FLOAT_EQ(pad->leftTrigger, 0.0f);
    report[0] = 0x11;  // a Bluetooth report: not decoded as USB
    EXPECT_FALSE(decodeDualShock4UsbReport(report).has_value());
}

TEST(HidReports, DualSenseUsbReport) {
    std::array<std::uint8_t, 64> report{};
    // Left stick full left, right stick full down, L2 half, counter, hat neutral, L1 held.
    const std::uint8_t head[] = {0x01, 0x00, 0x80, 0x80, 0xff, 0x80, 0x00, 0x2a, 0x08, 0x01, 0x00};
    std::copy(std::begin(head), std::end(head), report.begin());
    const auto pad = decodeDualSenseUsbReport(report);
    ASSERT_TRUE(pad.has_value());
    EXPECT_FLOAT_EQ(pad->leftStick.x, -1.0f);
    EXPECT_FLOAT_EQ(pad->rightStick.y, -1.0f);
    EXPECT_NEAR(pad->leftTrigger, 128.0f / 255.0f, 1e-6f);
    EXPECT_TRUE(pad->leftShoulder);
    EXPECT_FALSE(pad->rightShoulder);
    EXPECT_FALSE(decodeDualSenseUsbReport(std::vector<std::uint8_t>(5, 0x01)).has_value());
}

TEST(HidReports, DeadZonesZeroTheRestAndRescaleTheRest) {
    EXPECT_EQ(applyDeadZone(0.1f, 0.15f), 0.0f);
    EXPECT_EQ(applyDeadZone(-0.15f, 0.15f), 0.0f);
    EXPECT_NEAR(applyDeadZone(0.575f, 0.15f), 0.5f, 1e-6f);
    EXPECT_NEAR(applyDeadZone(-1.0f, 0.15f), -1.0f, 1e-6f);
    EXPECT_EQ(applyRadialDeadZone({0.1f, 0.1f}, 0.15f), glm::vec2(0.0f));
    const glm::vec2 diagonal = applyRadialDeadZone({0.6f, 0.8f}, 0.2f);  // length 1: stays 1, same direction
    EXPECT_NEAR(glm::length(diagonal), 1.0f, 1e-6f);
    EXPECT_NEAR(diagonal.x / diagonal.y, 0.75f, 1e-6f);
}

TEST(HidReports, GamepadAndSpaceMouseFlyTheCamera) {
    DeviceSettings settings;
    GamepadState pad;
    pad.leftStick = {0.0f, 1.0f};
    pad.rightStick = {0.05f, -1.0f};  // x inside the dead zone
    pad.rightTrigger = 1.0f;
    pad.rightShoulder = true;
    const FlightInput fromPad = gamepadFlightInput(pad, settings);
    EXPECT_NEAR(fromPad.move.z, 1.0f, 1e-6f);
    EXPECT_NEAR(fromPad.move.y, 1.0f, 1e-6f);
    EXPECT_LT(fromPad.turnRate.y, -0.99f);
    EXPECT_NEAR(fromPad.turnRate.x, 0.0f, 0.06f);
    EXPECT_TRUE(fromPad.boost);

    SpaceMouseState mouse;
    mouse.translation = {0, -350, 0};  // cap pushed away from the person
    mouse.rotation = {0, 0, 350};      // twisted clockwise
    const FlightInput fromMouse = spaceMouseFlightInput(mouse, settings);
    EXPECT_NEAR(fromMouse.move.z, 1.0f, 1e-6f);
    EXPECT_NEAR(fromMouse.turnRate.x, 1.0f, 1e-6f);
    mouse = {};
    mouse.translation = {10, 0, 0};  // a resting hand: inside the dead zone
    EXPECT_EQ(spaceMouseFlightInput(mouse, settings).move, glm::vec3(0.0f));
}

}  // namespace
}  // namespace firmament
