// Fuzz target: HID report decoders (SpaceMouse, DualShock 4, DualSense), fed every input as a
// report of each kind. Decoded sticks lie in [-1, 1], triggers in [0, 1], and the camera motion
// made from them is finite.
#include "FuzzSupport.h"

#include "input/HidReports.h"

#include <cmath>

namespace {

bool finite(const firmament::FlightInput& input) {
    return std::isfinite(input.move.x) && std::isfinite(input.move.y) && std::isfinite(input.move.z) &&
           std::isfinite(input.turnRate.x) && std::isfinite(input.turnRate.y);
}

void checkPad(const firmament::GamepadState& pad) {
    for (float v : {pad.leftStick.x, pad.leftStick.y, pad.rightStick.x, pad.rightStick.y}) FUZZ_CHECK(v >= -1.0f && v <= 1.0f);
    for (float v : {pad.leftTrigger, pad.rightTrigger}) FUZZ_CHECK(v >= 0.0f && v <= 1.0f);
    FUZZ_CHECK(finite(firmament::gamepadFlightInput(pad, firmament::DeviceSettings{})));
}

}  // namespace

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, size_t size) {
    using namespace firmament;
    const auto report = fuzz::bytesOf(data, size);
    SpaceMouseState mouse;
    if (decodeSpaceMouseReport(report, mouse)) FUZZ_CHECK(finite(spaceMouseFlightInput(mouse, DeviceSettings{})));
    if (const auto pad = decodeDualShock4UsbReport(report)) checkPad(*pad);
    if (const auto pad = decodeDualSenseUsbReport(report)) checkPad(*pad);
    return 0;
}
