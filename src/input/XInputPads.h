#pragma once
// Xbox pads through XInput (xinput1_4.dll, else xinput9_1_0.dll, loaded at run time so the
// program starts without them). Connected slots are read every frame; empty slots are
// checked every two seconds, since asking an empty slot is slow.
#include "input/HidReports.h"

#include <windows.h>
#include <xinput.h>

#include <array>

namespace firmament {

// XInput's pad state (sticks -32768..32767, triggers 0..255) in the common gamepad terms.
GamepadState gamepadFromXInput(const XINPUT_GAMEPAD& pad);

class XInputPads {
public:
    XInputPads();
    ~XInputPads();
    XInputPads(const XInputPads&) = delete;
    XInputPads& operator=(const XInputPads&) = delete;

    FlightInput poll(double secondsSinceStart, const DeviceSettings& settings);
    int connectedCount() const;

private:
    using GetStateFunction = DWORD(WINAPI*)(DWORD, XINPUT_STATE*);
    HMODULE library_ = nullptr;
    GetStateFunction getState_ = nullptr;
    std::array<bool, XUSER_MAX_COUNT> connected_{};
    double lastScan_ = -1e9;
};

}  // namespace firmament
