#include "support/CaptureRadiance.h"

#include "core/ExrImage.h"
#include "support/HeadlessCapture.h"

#include <Imath/half.h>
#include <gtest/gtest.h>

namespace firmament::test {

float exrChannel(const ExrFile& file, int x, int y, int c) {
    Imath::half h;
    h.setBits(file.image.halfBits[(static_cast<size_t>(y) * file.image.width + x) * 4 + c]);
    return static_cast<float>(h);
}

std::vector<float> exrRgb(const ExrFile& file) {
    std::vector<float> rgb;
    rgb.reserve(static_cast<size_t>(file.image.width) * file.image.height * 3);
    for (int y = 0; y < file.image.height; ++y)
        for (int x = 0; x < file.image.width; ++x)
            for (int c = 0; c < 3; ++c) rgb.push_back(exrChannel(file, x, y, c));
    return rgb;
}

std::vector<float> captureRadiance(const std::filesystem::path& folder, const std::string& name, const std::vector<std::wstring>& settings, int width,
                                   int height, int frames) {
    HeadlessCapture capture;
    capture.settings = settings;
    capture.width = width;
    capture.height = height;
    capture.frames = frames;
    capture.png = folder / (name + ".png");
    const ProcessResult run = captureHeadless(capture);
    EXPECT_EQ(run.exitCode, 0u) << run.output;
    if (run.exitCode != 0) return {};
    return exrRgb(readExr(folder / (name + ".exr")));
}

}  // namespace firmament::test
