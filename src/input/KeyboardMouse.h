#pragma once
// Keyboard and mouse state from window messages, turned into FlightInput once per frame:
// W/S forward and back, A/D strafe, Q/E down and up, Shift faster, the wheel changes the
// speed, a left-button drag turns the camera and a right-button drag turns the sun.
#include "input/FlyCamera.h"

#include <windows.h>

#include <bitset>

namespace firmament {

class KeyboardMouse {
public:
    // Feeds one window message. `guiHasMouse` / `guiHasKeyboard`: the GUI is using them, so
    // clicks, wheel and keys pressed there do not fly the camera.
    void onMessage(UINT message, WPARAM wParam, LPARAM lParam, bool guiHasMouse, bool guiHasKeyboard);
    void releaseAll();  // focus lost: no key stays held

    // The input for this frame; mouse motion and wheel are consumed, held keys remain.
    FlightInput takeFrameInput(const FlightSettings& settings);

    bool dragging() const { return cameraDrag_ || sunDrag_; }

private:
    bool held(int virtualKey) const { return keys_.test(static_cast<size_t>(virtualKey) & 0xff); }

    std::bitset<256> keys_;
    bool cameraDrag_ = false;
    bool sunDrag_ = false;
    bool havePosition_ = false;
    POINT lastPosition_{};
    POINT cameraPixels_{};  // accumulated drag since the last frame
    POINT sunPixels_{};
    int wheelDelta_ = 0;    // in WHEEL_DELTA units (120 per notch)
};

}  // namespace firmament
