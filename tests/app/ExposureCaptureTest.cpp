// Auto exposure in frames firmament.exe captures (docs/tonemapping.md, "Metering"):
//  - from orbit, histogram metering (the default) exposes the Earth and the sky at its limb
//    without clipping, where the log-average of every pixel, dragged down by black space, blows
//    them out;
//  - a static view's capture does not depend on how many frames were rendered before it: the
//    adaptation starts adapted, and the first frame uses its own measurement.
#include "core/PngImage.h"
#include "support/HeadlessCapture.h"
#include "support/TestPaths.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cstdio>
#include <cstdlib>
#include <string>
#include <vector>

namespace firmament::test {
namespace {

constexpr int kWidth = 240, kHeight = 135;

// `frames` headless frames of `settings`; the PNG captured after the last.
Rgba8Image capture(const std::string& name, const std::vector<std::wstring>& settings, int frames) {
    const auto folder = std::filesystem::temp_directory_path() / ("firmament-exposure-" + name);
    std::filesystem::remove_all(folder);
    const ProcessResult run = captureHeadless({{}, settings, kWidth, kHeight, frames, folder / "frame.png"});
    EXPECT_EQ(run.exitCode, 0u) << run.output;
    if (run.exitCode != 0) return {};
    Rgba8Image image = readPng(folder / "frame.png");
    std::filesystem::remove_all(folder);
    return image;
}

// The Earth from orbit, where auto exposure once went wrong: 400 km up, looking 30 degrees
// down, the sun 20 degrees up; the rest the program's defaults.
const std::vector<std::wstring> kOrbit{L"camera.position=0,400000,0", L"camera.pitch=-30", L"sun.elevation=20"};

// Of the pixels that are not black (the Earth and its atmosphere, not space), the share with a
// channel at 255.
double clippedShare(const Rgba8Image& image, int& lit) {
    int clipped = 0;
    lit = 0;
    for (size_t i = 0; i + 3 < image.pixels.size(); i += 4) {
        const int brightest = std::max({image.pixels[i], image.pixels[i + 1], image.pixels[i + 2]});
        if (brightest <= 8) continue;
        ++lit;
        clipped += brightest >= 255;
    }
    return lit > 0 ? static_cast<double>(clipped) / lit : 1.0;
}

TEST(ExposureCapture, FromOrbitTheEarthAndItsLimbDoNotClip) {
    const Rgba8Image histogram = capture("orbit-histogram", kOrbit, 3);
    std::vector<std::wstring> logAverage = kOrbit;
    logAverage.push_back(L"toneMapping.metering=Log average");
    const Rgba8Image everyPixel = capture("orbit-log-average", logAverage, 3);
    ASSERT_FALSE(histogram.pixels.empty());
    ASSERT_FALSE(everyPixel.pixels.empty());
    int lit = 0, litLogAverage = 0;
    const double clipped = clippedShare(histogram, lit), clippedLogAverage = clippedShare(everyPixel, litLogAverage);
    std::printf("from orbit: %d lit pixels of %d; clipped: %.2f%% (histogram), %.2f%% (log average)\n", lit, kWidth * kHeight, 100.0 * clipped,
                100.0 * clippedLogAverage);
    EXPECT_GT(lit, kWidth * kHeight / 2) << "the Earth should fill most of the frame";
    EXPECT_LT(lit, kWidth * kHeight) << "space should show above the limb";
    EXPECT_LT(clipped, 0.01);
    EXPECT_GT(clippedLogAverage, 0.05) << "the view no longer shows the log-average's failure";
}

// The largest difference of any channel between two captures.
int largestDifference(const Rgba8Image& a, const Rgba8Image& b) {
    if (a.pixels.size() != b.pixels.size()) return 256;
    int largest = 0;
    for (size_t i = 0; i < a.pixels.size(); ++i) largest = std::max(largest, std::abs(static_cast<int>(a.pixels[i]) - static_cast<int>(b.pixels[i])));
    return largest;
}

TEST(ExposureCapture, AStaticViewsCaptureDoesNotDependOnTheFrameCount) {
    struct View {
        const char* name;
        std::vector<std::wstring> settings;
    };
    // (The clouds drift with the wind and their particles pulse with time, so over the mountains
    // they are off: the frames would differ by their motion, not by the exposure. From orbit
    // their motion in a second is far below a pixel.)
    const std::vector<View> views{{"orbit", kOrbit},
                                  {"sunset over the mountains", {L"camera.position=0,3200,0", L"camera.yaw=100", L"camera.pitch=-4", L"sun.elevation=5",
                                                                 L"sun.azimuth=100", L"clouds.enabled=off"}}};
    for (const View& view : views) {
        const Rgba8Image after3 = capture("frames-3", view.settings, 3);
        const Rgba8Image after60 = capture("frames-60", view.settings, 60);
        ASSERT_FALSE(after3.pixels.empty()) << view.name;
        const int difference = largestDifference(after3, after60);
        std::printf("%s: after 3 and 60 frames, the largest difference is %d\n", view.name, difference);
        EXPECT_LE(difference, 1) << view.name;
    }
}

}  // namespace
}  // namespace firmament::test
