#include "input/HidDevices.h"

#include "core/Log.h"

#include <hidapi.h>

#include <algorithm>
#include <array>
#include <cstdint>

namespace firmament {

namespace {
constexpr double kEnumerationPeriodSeconds = 2.0;
}

struct HidDevices::Device {
    std::string path;
    std::string name;
    HidDeviceKind kind;
    hid_device* handle = nullptr;
    SpaceMouseState spaceMouse;
    GamepadState pad;

    ~Device() {
        if (handle) hid_close(handle);
    }
};

HidDevices::HidDevices() {
    initialized_ = hid_init() == 0;
    if (!initialized_) log::warning("hidapi did not start: HID devices are not used");
}

HidDevices::~HidDevices() {
    devices_.clear();
    if (initialized_) hid_exit();
}

void HidDevices::enumerate() {
    hid_device_info* list = hid_enumerate(0, 0);
    for (hid_device_info* info = list; info; info = info->next) {
        const auto kind = hidDeviceKind({info->vendor_id, info->product_id});
        if (!kind || !info->path) continue;
        if (std::any_of(devices_.begin(), devices_.end(), [&](const auto& d) { return d->path == info->path; })) continue;
        hid_device* handle = hid_open_path(info->path);
        if (!handle) continue;  // another interface of the same device, or no permission
        hid_set_nonblocking(handle, 1);
        auto device = std::make_unique<Device>();
        device->path = info->path;
        device->kind = *kind;
        device->name = std::string(hidDeviceKindName(*kind));
        device->handle = handle;
        log::info("HID device connected: " + device->name);
        devices_.push_back(std::move(device));
    }
    hid_free_enumeration(list);
}

FlightInput HidDevices::poll(double now, const DeviceSettings& settings) {
    FlightInput total;
    if (!initialized_ || !settings.enabled) return total;
    if (now - lastEnumeration_ >= kEnumerationPeriodSeconds) {
        lastEnumeration_ = now;
        enumerate();
    }
    std::array<std::uint8_t, 128> report{};
    for (auto it = devices_.begin(); it != devices_.end();) {
        Device& d = **it;
        int size = 0;
        while ((size = hid_read(d.handle, report.data(), report.size())) > 0) {
            const std::span<const std::uint8_t> bytes(report.data(), static_cast<size_t>(size));
            if (d.kind == HidDeviceKind::SpaceMouse) decodeSpaceMouseReport(bytes, d.spaceMouse);
            else if (const auto pad = d.kind == HidDeviceKind::DualShock4 ? decodeDualShock4UsbReport(bytes) : decodeDualSenseUsbReport(bytes))
                d.pad = *pad;
        }
        if (size < 0) {  // unplugged
            log::info("HID device disconnected: " + d.name);
            it = devices_.erase(it);
            continue;
        }
        total += d.kind == HidDeviceKind::SpaceMouse ? spaceMouseFlightInput(d.spaceMouse, settings)
                                                     : gamepadFlightInput(d.pad, settings);
        ++it;
    }
    return total;
}

std::vector<std::string> HidDevices::connectedNames() const {
    std::vector<std::string> names;
    for (const auto& d : devices_) names.push_back(d->name);
    return names;
}

}  // namespace firmament
