// firmament.exe end to end, headless and in a window: a few frames, a PNG that shows
// something (not a uniform image), an EXR whose pixels and header describe the frame.
#include "core/ExrImage.h"
#include "core/PngImage.h"
#include "support/Process.h"
#include "support/TestPaths.h"

#include <Imath/half.h>
#include <gtest/gtest.h>

#include <algorithm>
#include <map>

namespace firmament::test {
namespace {

// Not uniform: at least 1% of the pixels differ from the most common colour (the
// background); today that is the GUI overlay with the frame and pass times.
void expectNotUniform(const Rgba8Image& image) {
    std::map<std::uint32_t, size_t> histogram;
    for (size_t i = 0; i < image.pixels.size(); i += 4) {
        ++histogram[image.pixels[i] | image.pixels[i + 1] << 8 | image.pixels[i + 2] << 16];
        ASSERT_EQ(image.pixels[i + 3], 255);
    }
    size_t mostCommon = 0;
    for (const auto& [colour, count] : histogram) mostCommon = std::max(mostCommon, count);
    const size_t pixels = image.pixels.size() / 4;
    EXPECT_GE(histogram.size(), 3u);
    EXPECT_GT(pixels - mostCommon, pixels / 100) << "the captured frame is (nearly) uniform";
}

TEST(HeadlessRun, CapturesAPngAndASelfDescribingExr) {
    const auto folder = std::filesystem::temp_directory_path() / "firmament-headless-test";
    std::filesystem::remove_all(folder);
    const auto png = folder / "frame.png", exr = folder / "frame.exr";

    const ProcessResult run =
        runProcess(firmamentExe(), {L"--headless", L"--frames", L"4", L"--resolution", L"320x200", L"--capture", png.wstring()});
    ASSERT_EQ(run.exitCode, 0u) << run.output;
    EXPECT_NE(run.output.find("GPU time per pass over 4 frames at 320x200"), std::string::npos) << run.output;
    EXPECT_NE(run.output.find("Display encode"), std::string::npos) << run.output;

    const Rgba8Image image = readPng(png);
    ASSERT_EQ(image.width, 320);
    ASSERT_EQ(image.height, 200);
    expectNotUniform(image);

    const ExrFile file = readExr(exr);
    ASSERT_EQ(file.image.width, 320);
    ASSERT_EQ(file.image.height, 200);
    // The HDR frame before display encoding: no technique draws yet, so the bottom-right
    // pixel (far from the overlay) holds the background radiance, in linear units.
    const size_t corner = (static_cast<size_t>(199) * 320 + 319) * 4;
    Imath::half r, b;
    r.setBits(file.image.halfBits[corner]);
    b.setBits(file.image.halfBits[corner + 2]);
    EXPECT_NEAR(static_cast<float>(r), 0.02f, 1e-4f);
    EXPECT_NEAR(static_cast<float>(b), 0.035f, 1e-4f);

    const auto& a = file.attributes;
    for (const char* name : {"firmament.version", "firmament.resolution", "firmament.view", "firmament.projection",
                             "firmament.directionToSun", "firmament.settings", "firmament.adapter", "firmament.frame"})
        EXPECT_TRUE(a.count(name)) << "missing header attribute " << name;
    EXPECT_EQ(std::get<glm::ivec2>(a.at("firmament.resolution")), glm::ivec2(320, 200));
    EXPECT_EQ(std::get<int>(a.at("firmament.frame")), 4);
    const std::string settings = std::get<std::string>(a.at("firmament.settings"));
    EXPECT_NE(settings.find("display.resolution = 320x200"), std::string::npos) << settings;
    EXPECT_NE(settings.find("device.driver = warp"), std::string::npos) << settings;
    EXPECT_NEAR(glm::length(std::get<glm::vec3>(a.at("firmament.directionToSun"))), 1.0f, 1e-5f);
    // The projection matches the frame's aspect ratio: m[1][1] / m[0][0] = width / height.
    const glm::mat4 projection = std::get<glm::mat4>(a.at("firmament.projection"));
    EXPECT_NEAR(projection[1][1] / projection[0][0], 320.0f / 200.0f, 1e-4f);
    std::filesystem::remove_all(folder);
}

// A visible window: the flip-model swap chain, presentation without VSync, and the capture
// read from the back buffer before it is presented.
TEST(WindowedRun, PresentsThroughTheSwapChainAndCaptures) {
    const auto folder = std::filesystem::temp_directory_path() / "firmament-windowed-test";
    std::filesystem::remove_all(folder);
    const ProcessResult run = runProcess(firmamentExe(), {L"--frames", L"5", L"--resolution", L"300x180", L"--vsync", L"off",
                                                          L"--capture", (folder / "window.png").wstring()});
    ASSERT_EQ(run.exitCode, 0u) << run.output;
    EXPECT_NE(run.output.find("GPU time per pass over 5 frames"), std::string::npos) << run.output;
    const Rgba8Image image = readPng(folder / "window.png");
    EXPECT_GT(image.width, 0);
    EXPECT_GT(image.height, 0);
    expectNotUniform(image);
    std::filesystem::remove_all(folder);
}

}  // namespace
}  // namespace firmament::test
