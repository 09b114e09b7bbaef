// The demo's flight (media/flights/demo.json) shows what the README says it shows: each named
// capture is the view of a keyframe (so any time step that falls on the keyframes gives the same
// pictures), the sunrise and haze views are under the default cloud layer and the clouds view
// above it, the flight ends 40 km up, and no capture is dark or blown out.
#include "core/ExrImage.h"
#include "core/PngImage.h"
#include "support/Process.h"
#include "support/TestPaths.h"

#include <gtest/gtest.h>

#include <nlohmann/json.hpp>

#include <cmath>
#include <cstdio>
#include <fstream>
#include <string>
#include <vector>

namespace firmament::test {
namespace {

// The share of pixels with a channel at 255, and the mean of Rec. 709 luma on the 0-255 scale.
struct Exposure {
    double clipped = 0.0, meanLuma = 0.0;
};
Exposure measureExposure(const Rgba8Image& image) {
    size_t clipped = 0;
    double luma = 0.0;
    for (int y = 0; y < image.height; ++y)
        for (int x = 0; x < image.width; ++x) {
            const std::uint8_t* p = image.pixel(x, y);
            if (p[0] == 255 || p[1] == 255 || p[2] == 255) ++clipped;
            luma += 0.2126 * p[0] + 0.7152 * p[1] + 0.0722 * p[2];
        }
    const double count = static_cast<double>(image.width) * image.height;
    return {clipped / count, luma / count};
}

TEST(DemoFlight, EveryCaptureIsAKeyframesViewUnderOrAboveTheCloudsAndWellExposed) {
    const auto folder = std::filesystem::temp_directory_path() / "firmament-demo-flight";
    std::filesystem::remove_all(folder);
    const auto flightFile = executableFolder() / "media" / "flights" / "demo.json";
    nlohmann::json flight;
    {
        std::ifstream in(flightFile);
        flight = nlohmann::json::parse(in);
    }
    const nlohmann::json& keyframes = flight["keyframes"];
    ASSERT_EQ(keyframes.back()["time"], 4.0) << "the soak schedule's loop is the flight's length, 240 frames at 60 Hz";

    // Steps of 0.4 s fall on every keyframe (0, 1.2, 2.4, 4.0 s): 11 frames.
    const ProcessResult run = runProcess(firmamentExe(), {L"--headless", L"--resolution", L"256x144", L"--flight", flightFile.wstring(),
                                                          L"--time-step", L"0.4", L"--capture", (folder / "demo.png").wstring()});
    ASSERT_EQ(run.exitCode, 0u) << run.output;

    // The keyframe at `time`, with the camera and sun keys a keyframe leaves out taken from the ones before.
    const auto keyframeAt = [&](double time) {
        nlohmann::json view = nlohmann::json::object();
        for (const nlohmann::json& k : keyframes) {
            for (const char* section : {"camera", "sun"})
                if (k.contains(section))
                    for (const auto& [key, value] : k[section].items()) view[section][key] = value;
            if (std::abs(k["time"].get<double>() - time) < 1e-9) return view;
        }
        ADD_FAILURE() << "no keyframe at " << time << " s: a capture between keyframes depends on the time step";
        return view;
    };
    struct Shot {
        std::string name;
        double time;
    };
    std::vector<Shot> shots;
    for (const nlohmann::json& c : flight["captures"]) shots.push_back({c["name"].get<std::string>(), c["time"].get<double>()});
    shots.push_back({"", 4.0});  // the last frame, demo.png
    ASSERT_EQ(shots.size(), 4u);

    for (const Shot& shot : shots) {
        const std::string stem = shot.name.empty() ? "demo" : "demo-" + shot.name;
        SCOPED_TRACE(stem + " at " + std::to_string(shot.time) + " s");
        const nlohmann::json expected = keyframeAt(shot.time);
        const auto settings = nlohmann::json::parse(std::get<std::string>(readExr(folder / (stem + ".exr")).attributes.at("firmament.settings")));
        for (int axis = 0; axis < 3; ++axis)
            EXPECT_NEAR(settings["camera"]["position"][axis].get<double>(), expected["camera"]["position"][axis].get<double>(), 1e-3);
        for (const char* key : {"yaw", "pitch"})
            EXPECT_NEAR(settings["camera"][key].get<double>(), expected["camera"][key].get<double>(), 1e-4) << key;
        for (const char* key : {"elevation", "azimuth"})
            EXPECT_NEAR(settings["sun"][key].get<double>(), expected["sun"][key].get<double>(), 1e-4) << key;

        // The story the README tells, against the cloud layer's defaults.
        const double altitude = settings["camera"]["position"][1].get<double>();
        const double layerBottom = settings["clouds"]["altitude"].get<double>() - 0.5 * settings["clouds"]["thickness"].get<double>();
        const double layerTop = settings["clouds"]["altitude"].get<double>() + 0.5 * settings["clouds"]["thickness"].get<double>();
        if (shot.name == "sunrise" || shot.name == "haze") {
            EXPECT_LT(altitude, layerBottom);
        }
        if (shot.name == "sunrise") {
            EXPECT_LT(settings["sun"]["elevation"].get<double>(), 5.0);
        }
        if (shot.name == "clouds") {
            EXPECT_GT(altitude, layerTop);
        }
        if (shot.name.empty()) {
            EXPECT_GE(altitude, 40000.0);
        }

        // Metered, not dark and not blown out. Measured at 256x144 (2026-12-03): mean luma 121 to
        // 150; a share of 0.7% to 7% clipped, the most in the sunrise's glow around the sun. Since
        // deck diffusion's deck ends at a gap of clear air (2026-12-07), the low sun's deck has
        // dark bodies with lit edges instead of a flat gold (docs/clouds.md, "Deck diffusion"), the
        // metered exposure rises, and the glow band along the horizon clips more: mean luma 125 to
        // 143; 0.1% to 12.3% clipped (the sunrise 12.3%, the haze 9.4%).
        const Exposure exposure = measureExposure(readPng(folder / (stem + ".png")));
        EXPECT_GT(exposure.meanLuma, 70.0);
        EXPECT_LT(exposure.meanLuma, 190.0);
        EXPECT_LT(exposure.clipped, 0.16);
        std::printf("%s: mean luma %.1f, %.2f%% of the pixels clipped\n", stem.c_str(), exposure.meanLuma, 100.0 * exposure.clipped);
    }
    std::filesystem::remove_all(folder);
}

}  // namespace
}  // namespace firmament::test
