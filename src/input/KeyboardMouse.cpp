#include "input/KeyboardMouse.h"

#include <windowsx.h>

namespace firmament {

void KeyboardMouse::onMessage(UINT message, WPARAM wParam, LPARAM lParam, bool guiHasMouse, bool guiHasKeyboard) {
    switch (message) {
        case WM_KEYDOWN:
        case WM_SYSKEYDOWN:
            if (!guiHasKeyboard) keys_.set(wParam & 0xff);
            break;
        case WM_KEYUP:
        case WM_SYSKEYUP:
            keys_.reset(wParam & 0xff);  // always: a key pressed before the GUI took focus must not stick
            break;
        case WM_KILLFOCUS:
            releaseAll();
            break;
        case WM_LBUTTONDOWN:
        case WM_RBUTTONDOWN:
            if (guiHasMouse) break;
            (message == WM_LBUTTONDOWN ? cameraDrag_ : sunDrag_) = true;
            lastPosition_ = {GET_X_LPARAM(lParam), GET_Y_LPARAM(lParam)};
            havePosition_ = true;
            break;
        case WM_LBUTTONUP:
            cameraDrag_ = false;
            break;
        case WM_RBUTTONUP:
            sunDrag_ = false;
            break;
        case WM_MOUSEMOVE: {
            const POINT p{GET_X_LPARAM(lParam), GET_Y_LPARAM(lParam)};
            if (havePosition_ && cameraDrag_) {
                cameraPixels_.x += p.x - lastPosition_.x;
                cameraPixels_.y += p.y - lastPosition_.y;
            }
            if (havePosition_ && sunDrag_) {
                sunPixels_.x += p.x - lastPosition_.x;
                sunPixels_.y += p.y - lastPosition_.y;
            }
            lastPosition_ = p;
            havePosition_ = true;
            break;
        }
        case WM_MOUSEWHEEL:
            if (!guiHasMouse) wheelDelta_ += GET_WHEEL_DELTA_WPARAM(wParam);
            break;
        default:
            break;
    }
}

void KeyboardMouse::releaseAll() {
    keys_.reset();
    cameraDrag_ = sunDrag_ = false;
}

FlightInput KeyboardMouse::takeFrameInput(const FlightSettings& settings) {
    FlightInput in;
    auto axis = [&](int positive, int negative) { return (held(positive) ? 1.0f : 0.0f) - (held(negative) ? 1.0f : 0.0f); };
    in.move = {axis('D', 'A'), axis('E', 'Q'), axis('W', 'S')};
    in.boost = held(VK_SHIFT) || held(VK_LSHIFT) || held(VK_RSHIFT);
    // Screen y grows downwards: dragging up looks up and raises the sun.
    in.turnDegrees = glm::vec2(static_cast<float>(cameraPixels_.x), static_cast<float>(-cameraPixels_.y)) *
                     settings.mouseDegreesPerPixel;
    in.sunTurnDegrees = glm::vec2(static_cast<float>(sunPixels_.x), static_cast<float>(-sunPixels_.y)) *
                        settings.sunDegreesPerPixel;
    in.speedSteps = wheelDelta_ / WHEEL_DELTA;
    wheelDelta_ -= in.speedSteps * WHEEL_DELTA;  // keep a partial notch (precision touchpads)
    cameraPixels_ = sunPixels_ = POINT{};
    return in;
}

}  // namespace firmament
