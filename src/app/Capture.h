#pragma once
// Captures of the final frame: the display image as PNG and the HDR frame as OpenEXR (half
// float RGBA, or 32-bit float with --hdr-float32). The EXR header describes the frame: resolution, camera matrices, sun
// direction, the settings as JSON, the adapter and the Direct3D 11 implementation, the program
// version, and what the techniques record of themselves (the exposure and operator of the tone
// mapping).
#include "core/Camera.h"
#include "core/ExrImage.h"
#include "gpu/Readback.h"

#include <filesystem>
#include <string>

namespace firmament {

struct CaptureDescription {
    glm::mat4 view{1.0f};
    glm::mat4 projection{1.0f};
    glm::vec3 directionToSun{0.0f, 1.0f, 0.0f};
    std::string settings;  // "name = value" lines
    std::string adapter;
    std::string implementation;  // implementationId: "wined3d", "dxvk", "windows"
    int frame = 0;
    ExrAttributes techniques;  // what each technique records of itself ("firmament.toneMapping.*", ...)
};

ExrAttributes captureAttributes(const CaptureDescription& description, int width, int height);

// display: 8-bit RGBA (already sRGB encoded); hdr: RGBA16F, or RGBA32F (written as a 32-bit
// float EXR). Throws Error.
void writeCapture(const std::filesystem::path& pngPath, const std::filesystem::path& exrPath,
                  const ReadbackImage& display, const ReadbackImage& hdr, const CaptureDescription& description);

}  // namespace firmament
