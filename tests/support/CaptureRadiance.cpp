#include "support/CaptureRadiance.h"

#include "core/ExrImage.h"
#include "support/HeadlessCapture.h"

#include <Imath/half.h>
#include <gtest/gtest.h>

namespace firmament::test {

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
    const ExrFile file = readExr(folder / (name + ".exr"));
    std::vector<float> rgb;
    rgb.reserve(static_cast<size_t>(width) * height * 3);
    for (size_t i = 0; i < static_cast<size_t>(width) * height; ++i)
        for (int c = 0; c < 3; ++c) {
            Imath::half h;
            h.setBits(file.image.halfBits[i * 4 + c]);
            rgb.push_back(static_cast<float>(h));
        }
    return rgb;
}

}  // namespace firmament::test
