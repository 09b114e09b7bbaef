// XInput pads' state (Windows only: the structure comes from <xinput.h>), mapped to the same
// gamepad state as the HID decoders' (HidReportsTest.cpp).
#include "input/XInputPads.h"

#include <gtest/gtest.h>

namespace firmament {
namespace {

TEST(HidReports, XInputPadState) {
    XINPUT_GAMEPAD raw{};
    raw.sThumbLX = -32768;
    raw.sThumbLY = 32767;
    raw.bLeftTrigger = 255;
    raw.wButtons = XINPUT_GAMEPAD_RIGHT_SHOULDER;
    const GamepadState pad = gamepadFromXInput(raw);
    EXPECT_FLOAT_EQ(pad.leftStick.x, -1.0f);
    EXPECT_FLOAT_EQ(pad.leftStick.y, 1.0f);
    EXPECT_FLOAT_EQ(pad.leftTrigger, 1.0f);
    EXPECT_TRUE(pad.rightShoulder);
}

}  // namespace
}  // namespace firmament
