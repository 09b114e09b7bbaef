// Window messages to flight input: held keys, drags, the wheel, and the GUI keeping what
// it uses.
#include "input/KeyboardMouse.h"

#include <gtest/gtest.h>

namespace firmament {
namespace {

LPARAM at(int x, int y) { return MAKELPARAM(x, y); }

TEST(KeyboardMouse, HeldKeysMoveUntilReleased) {
    KeyboardMouse input;
    FlightSettings settings;
    input.onMessage(WM_KEYDOWN, 'W', 0, false, false);
    input.onMessage(WM_KEYDOWN, 'A', 0, false, false);
    input.onMessage(WM_KEYDOWN, 'E', 0, false, false);
    input.onMessage(WM_KEYDOWN, VK_SHIFT, 0, false, false);
    FlightInput in = input.takeFrameInput(settings);
    EXPECT_EQ(in.move, glm::vec3(-1.0f, 1.0f, 1.0f));
    EXPECT_TRUE(in.boost);
    EXPECT_EQ(input.takeFrameInput(settings).move, glm::vec3(-1.0f, 1.0f, 1.0f));  // still held next frame
    input.onMessage(WM_KEYUP, 'W', 0, false, false);
    input.onMessage(WM_KEYDOWN, 'S', 0, false, false);
    EXPECT_EQ(input.takeFrameInput(settings).move.z, -1.0f);
    input.onMessage(WM_KILLFOCUS, 0, 0, false, false);
    EXPECT_EQ(input.takeFrameInput(settings).move, glm::vec3(0.0f));
}

TEST(KeyboardMouse, LeftDragTurnsTheCameraRightDragTheSun) {
    KeyboardMouse input;
    FlightSettings settings;
    settings.mouseDegreesPerPixel = 0.5f;
    settings.sunDegreesPerPixel = 0.25f;
    input.onMessage(WM_LBUTTONDOWN, MK_LBUTTON, at(100, 100), false, false);
    input.onMessage(WM_MOUSEMOVE, MK_LBUTTON, at(110, 96), false, false);
    input.onMessage(WM_MOUSEMOVE, MK_LBUTTON, at(120, 90), false, false);
    FlightInput in = input.takeFrameInput(settings);
    EXPECT_EQ(in.turnDegrees, glm::vec2(10.0f, 5.0f));  // right and up
    EXPECT_EQ(in.sunTurnDegrees, glm::vec2(0.0f));
    EXPECT_EQ(input.takeFrameInput(settings).turnDegrees, glm::vec2(0.0f));  // consumed
    input.onMessage(WM_LBUTTONUP, 0, at(120, 90), false, false);
    input.onMessage(WM_RBUTTONDOWN, MK_RBUTTON, at(120, 90), false, false);
    input.onMessage(WM_MOUSEMOVE, MK_RBUTTON, at(80, 110), false, false);
    in = input.takeFrameInput(settings);
    EXPECT_EQ(in.sunTurnDegrees, glm::vec2(-10.0f, -5.0f));
    EXPECT_EQ(in.turnDegrees, glm::vec2(0.0f));
}

TEST(KeyboardMouse, WheelStepsAndTheGuiKeepsItsInput) {
    KeyboardMouse input;
    FlightSettings settings;
    input.onMessage(WM_MOUSEWHEEL, MAKEWPARAM(0, 2 * WHEEL_DELTA), 0, false, false);
    input.onMessage(WM_MOUSEWHEEL, MAKEWPARAM(0, 60), 0, false, false);  // half a notch: kept for later
    EXPECT_EQ(input.takeFrameInput(settings).speedSteps, 2);
    input.onMessage(WM_MOUSEWHEEL, MAKEWPARAM(0, 60), 0, false, false);
    EXPECT_EQ(input.takeFrameInput(settings).speedSteps, 1);
    // Over the GUI: no drag starts, no wheel, no key.
    input.onMessage(WM_MOUSEWHEEL, MAKEWPARAM(0, WHEEL_DELTA), 0, true, false);
    input.onMessage(WM_LBUTTONDOWN, MK_LBUTTON, at(10, 10), true, false);
    input.onMessage(WM_MOUSEMOVE, MK_LBUTTON, at(50, 10), true, false);
    input.onMessage(WM_KEYDOWN, 'W', 0, false, true);
    const FlightInput in = input.takeFrameInput(settings);
    EXPECT_EQ(in.speedSteps, 0);
    EXPECT_EQ(in.turnDegrees, glm::vec2(0.0f));
    EXPECT_EQ(in.move, glm::vec3(0.0f));
}

}  // namespace
}  // namespace firmament
