#include "input/XInputPads.h"

#include "core/Log.h"

#include <algorithm>

namespace firmament {

namespace {
constexpr double kScanPeriodSeconds = 2.0;
float thumbAxis(SHORT value) { return std::max(static_cast<float>(value) / 32767.0f, -1.0f); }
}  // namespace

GamepadState gamepadFromXInput(const XINPUT_GAMEPAD& pad) {
    GamepadState state;
    state.leftStick = {thumbAxis(pad.sThumbLX), thumbAxis(pad.sThumbLY)};  // XInput's y is already up
    state.rightStick = {thumbAxis(pad.sThumbRX), thumbAxis(pad.sThumbRY)};
    state.leftTrigger = pad.bLeftTrigger / 255.0f;
    state.rightTrigger = pad.bRightTrigger / 255.0f;
    state.leftShoulder = pad.wButtons & XINPUT_GAMEPAD_LEFT_SHOULDER;
    state.rightShoulder = pad.wButtons & XINPUT_GAMEPAD_RIGHT_SHOULDER;
    return state;
}

XInputPads::XInputPads() {
    for (const wchar_t* name : {L"xinput1_4.dll", L"xinput9_1_0.dll"}) {
        if ((library_ = LoadLibraryW(name))) break;
    }
    if (library_) getState_ = reinterpret_cast<GetStateFunction>(reinterpret_cast<void*>(GetProcAddress(library_, "XInputGetState")));
    if (!getState_) log::info("XInput is not available: Xbox pads are not used");
}

XInputPads::~XInputPads() {
    if (library_) FreeLibrary(library_);
}

FlightInput XInputPads::poll(double now, const DeviceSettings& settings) {
    FlightInput total;
    if (!getState_ || !settings.enabled) return total;
    const bool scan = now - lastScan_ >= kScanPeriodSeconds;
    if (scan) lastScan_ = now;
    for (DWORD slot = 0; slot < XUSER_MAX_COUNT; ++slot) {
        if (!connected_[slot] && !scan) continue;
        XINPUT_STATE state{};
        const bool connected = getState_(slot, &state) == ERROR_SUCCESS;
        if (connected != connected_[slot])
            log::info("Xbox pad " + std::to_string(slot + 1) + (connected ? " connected" : " disconnected"));
        connected_[slot] = connected;
        if (connected) total += gamepadFlightInput(gamepadFromXInput(state.Gamepad), settings);
    }
    return total;
}

int XInputPads::connectedCount() const { return static_cast<int>(std::count(connected_.begin(), connected_.end(), true)); }

}  // namespace firmament
