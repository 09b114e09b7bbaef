#pragma once
// The HID devices that fly the camera, through hidapi: looked for every two seconds while
// the program runs (hot-plug), read without blocking every frame, dropped when unplugged.
// Under Wine none is present and this finds nothing, which is fine.
#include "input/HidReports.h"

#include <memory>
#include <string>
#include <vector>

struct hid_device_;

namespace firmament {

class HidDevices {
public:
    HidDevices();
    ~HidDevices();
    HidDevices(const HidDevices&) = delete;
    HidDevices& operator=(const HidDevices&) = delete;

    // Reads every pending report; looks for new devices when `secondsSinceStart` has moved
    // two seconds past the last look. Returns the combined input of all devices.
    FlightInput poll(double secondsSinceStart, const DeviceSettings& settings);

    std::vector<std::string> connectedNames() const;

private:
    struct Device;
    void enumerate();

    bool initialized_ = false;
    double lastEnumeration_ = -1e9;
    std::vector<std::unique_ptr<Device>> devices_;
};

}  // namespace firmament
