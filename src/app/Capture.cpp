#include "app/Capture.h"

#include "core/Error.h"
#include "core/PngImage.h"
#include "FirmamentVersion.h"

#include <cstring>

namespace firmament {

ExrAttributes captureAttributes(const CaptureDescription& d, int width, int height) {
    ExrAttributes attributes{
        {"firmament.version", std::string(kFirmamentVersion)},
        {"firmament.resolution", glm::ivec2(width, height)},
        {"firmament.view", d.view},
        {"firmament.projection", d.projection},
        {"firmament.directionToSun", d.directionToSun},
        {"firmament.settings", d.settings},
        {"firmament.adapter", d.adapter},
        {"firmament.d3d11", d.implementation},
        {"firmament.frame", d.frame},
    };
    attributes.insert(d.techniques.begin(), d.techniques.end());
    return attributes;
}

void writeCapture(const std::filesystem::path& pngPath, const std::filesystem::path& exrPath,
                  const ReadbackImage& display, const ReadbackImage& hdr, const CaptureDescription& description) {
    if (display.bytesPerPixel != 4 || (hdr.bytesPerPixel != 8 && hdr.bytesPerPixel != 16)) throw Error("writeCapture: unexpected target formats");

    Rgba8Image png{display.width, display.height, display.bytes};
    for (size_t i = 3; i < png.pixels.size(); i += 4) png.pixels[i] = 255;  // the display has no alpha
    writePng(pngPath, png);

    const ExrAttributes attributes = captureAttributes(description, hdr.width, hdr.height);
    if (hdr.bytesPerPixel == 16) {  // --hdr-float32
        FloatRgbaImage exr{hdr.width, hdr.height, std::vector<float>(hdr.bytes.size() / 4)};
        std::memcpy(exr.rgba.data(), hdr.bytes.data(), hdr.bytes.size());
        writeExr(exrPath, exr, attributes);
        return;
    }
    HalfRgbaImage exr{hdr.width, hdr.height, std::vector<std::uint16_t>(hdr.bytes.size() / 2)};
    std::memcpy(exr.halfBits.data(), hdr.bytes.data(), hdr.bytes.size());
    writeExr(exrPath, exr, attributes);
}

}  // namespace firmament
