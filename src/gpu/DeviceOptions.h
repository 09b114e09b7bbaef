#pragma once
// How the Direct3D device is chosen: a hardware adapter by default, the WARP software
// rasterizer (tests, headless runs), or a DXGI adapter by index.
#include <optional>

namespace firmament {

enum class DriverType { Hardware, Warp };

struct DeviceOptions {
    DriverType driver = DriverType::Hardware;
    std::optional<unsigned> adapterIndex;  // overrides `driver`
    bool debugLayer = false;
};

}  // namespace firmament
