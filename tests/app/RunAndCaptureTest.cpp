// firmament.exe end to end, headless and in a window: a few frames, a PNG that shows
// something (not a uniform image), an EXR whose pixels and header describe the frame.
#include "core/ExrImage.h"
#include "core/PngImage.h"
#include "postfx/ToneMappingCurves.h"
#include "support/CaptureRadiance.h"
#include "support/HeadlessCapture.h"
#include "support/Process.h"
#include "support/TestPaths.h"

#include <gtest/gtest.h>

#include <nlohmann/json.hpp>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <cwchar>
#include <fstream>
#include <map>
#include <string>
#include <vector>

namespace firmament::test {
namespace {

// Not uniform: at least 1% of the pixels differ from the most common colour.
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

// A cheap scene for the tests of plumbing (panels, flights, operators): the sky and the
// orientation grid, without the clouds (seconds a frame on the CPU, whatever the image size)
// and the terrain (its cascades and draw; with it off, the height field is not even read).
const std::vector<std::wstring> kCheapScene{L"--set", L"clouds.enabled=off", L"--set", L"terrain.enabled=off"};

std::vector<std::wstring> withCheapScene(std::vector<std::wstring> arguments) {
    arguments.insert(arguments.end(), kCheapScene.begin(), kCheapScene.end());
    return arguments;
}

// With the orientation grid, light scattering and the terrain off nothing draws: the HDR frame holds the background
// radiance everywhere, and the PNG, without the GUI (left out by default), is uniform. Its
// colour is the background tone mapped with the default settings (Uncharted 2, auto
// exposure: the background's own luminance is the average), as the CPU reference predicts.
TEST(HeadlessRun, CapturesAPngAndASelfDescribingExr) {
    const auto folder = std::filesystem::temp_directory_path() / "firmament-headless-test";
    std::filesystem::remove_all(folder);
    const auto png = folder / "frame.png", exr = folder / "frame.exr";

    const ProcessResult run =
        runProcess(firmamentExe(), {L"--headless", L"--frames", L"4", L"--resolution", L"320x200", L"--capture", png.wstring(),
                                    L"--set", L"scene.orientationGrid=off", L"--set", L"atmosphere.enabled=off",
                                    L"--set", L"terrain.enabled=off", L"--set", L"camera.fieldOfView=60"});
    ASSERT_EQ(run.exitCode, 0u) << run.output;
    EXPECT_NE(run.output.find("GPU time per pass over 4 frames at 320x200"), std::string::npos) << run.output;
    // With the terrain off, the 16 MiB height field is never read (nor generated).
    EXPECT_EQ(run.output.find("terrain: height field"), std::string::npos) << run.output;
    EXPECT_EQ(run.output.find("terrain: generating the height field"), std::string::npos) << run.output;
    for (const char* pass : {"Scene luminance", "Light adaptation", "Tone mapping"})
        EXPECT_NE(run.output.find(pass), std::string::npos) << pass << "\n" << run.output;

    const Rgba8Image image = readPng(png);
    ASSERT_EQ(image.width, 320);
    ASSERT_EQ(image.height, 200);
    for (size_t i = 0; i < image.pixels.size(); i += 4)
        ASSERT_EQ(image.pixels[i] | image.pixels[i + 1] << 8 | image.pixels[i + 2] << 16,
                  image.pixels[0] | image.pixels[1] << 8 | image.pixels[2] << 16)
            << "pixel " << i / 4 << " differs: the GUI (or something else) was captured";

    const ExrFile file = readExr(exr);
    ASSERT_EQ(file.image.width, 320);
    ASSERT_EQ(file.image.height, 200);
    EXPECT_NEAR(exrChannel(file, 319, 199, 0), 0.02f, 1e-4f);
    EXPECT_NEAR(exrChannel(file, 319, 199, 2), 0.035f, 1e-4f);

    const glm::dvec3 background(exrChannel(file, 0, 0, 0), exrChannel(file, 0, 0, 1), exrChannel(file, 0, 0, 2));
    const double averageLuminance = tonemap::kLogLuminanceDelta + tonemap::relativeLuminance(background);
    const double exposure = tonemap::autoExposure(averageLuminance, 0.18, 1.0);
    const glm::dvec3 display = tonemap::toDisplay(background, {ToneMapOperator::Uncharted2, exposure, 3.0, 1.0});
    for (int c = 0; c < 3; ++c) EXPECT_NEAR(image.pixels[c], 255.0 * display[c], 1.0) << "channel " << c;

    const auto& a = file.attributes;
    for (const char* name : {"firmament.version", "firmament.resolution", "firmament.view", "firmament.projection",
                             "firmament.directionToSun", "firmament.settings", "firmament.adapter", "firmament.d3d11", "firmament.frame"})
        ASSERT_TRUE(a.count(name)) << "missing header attribute " << name;
    // The implementation the tools chose is the one that ran.
    EXPECT_EQ(std::get<std::string>(a.at("firmament.d3d11")), chosenD3D11Implementation());
    EXPECT_EQ(std::get<glm::ivec2>(a.at("firmament.resolution")), glm::ivec2(320, 200));
    EXPECT_EQ(std::get<int>(a.at("firmament.frame")), 4);
    // The tone mapping records what it applied.
    EXPECT_EQ(std::get<std::string>(a.at("firmament.toneMapping.operator")), "Uncharted 2");
    EXPECT_NEAR(std::get<float>(a.at("firmament.toneMapping.exposure")), exposure, 1e-3 * exposure);
    EXPECT_NEAR(std::get<float>(a.at("firmament.toneMapping.averageLuminance")), averageLuminance, 1e-3 * averageLuminance);
    EXPECT_EQ(std::get<int>(a.at("firmament.toneMapping.autoExposure")), 1);
    // The settings are the whole state as JSON, loadable again with --settings.
    const auto settings = nlohmann::json::parse(std::get<std::string>(a.at("firmament.settings")));
    EXPECT_EQ(settings["camera"]["fieldOfView"], 60.0);
    EXPECT_EQ(settings["scene"]["orientationGrid"], false);
    EXPECT_NEAR(glm::length(std::get<glm::vec3>(a.at("firmament.directionToSun"))), 1.0f, 1e-5f);
    // The projection matches the frame's aspect ratio (m[1][1] / m[0][0] = width / height)
    // and the field of view that was set (m[1][1] = 1 / tan(30 degrees)).
    const glm::mat4 projection = std::get<glm::mat4>(a.at("firmament.projection"));
    EXPECT_NEAR(projection[1][1] / projection[0][0], 320.0f / 200.0f, 1e-4f);
    EXPECT_NEAR(projection[1][1], 1.0f / std::tan(glm::radians(30.0f)), 1e-4f);
    std::filesystem::remove_all(folder);
}

// The orientation grid on its own (light scattering and the terrain off): its sky above the horizon and the
// ground below. A saved state file sets the view: looking down 10 degrees from 500 m.
TEST(HeadlessRun, DrawsTheOrientationGridFromASettingsFile) {
    const auto folder = std::filesystem::temp_directory_path() / "firmament-grid-test";
    std::filesystem::remove_all(folder);
    std::filesystem::create_directories(folder);
    std::ofstream(folder / "view.json") << R"({"camera": {"position": [0, 500, 0], "pitch": -10}, "sun": {"elevation": 45}, "atmosphere": {"enabled": false}, "terrain": {"enabled": false}})";
    const ProcessResult run = runProcess(firmamentExe(), {L"--headless", L"--frames", L"2", L"--resolution", L"256x256",
                                                          L"--settings", (folder / "view.json").wstring(), L"--capture",
                                                          (folder / "grid.png").wstring()});
    ASSERT_EQ(run.exitCode, 0u) << run.output;
    EXPECT_NE(run.output.find("Orientation grid"), std::string::npos) << run.output;
    const ExrFile file = readExr(folder / "grid.exr");
    // Top row: 22.5 - 10 = 12.5 degrees above the horizon: sky, bluer than red.
    EXPECT_GT(exrChannel(file, 128, 0, 2), exrChannel(file, 128, 0, 0));
    // Bottom row: ground, lit by a sun 45 degrees high: albedo * (3 sin 45 + 0.15), hazed
    // by exp(-distance / 60 km) over the 930 m to the ground 32.5 degrees below.
    const float red = exrChannel(file, 128, 255, 0);
    const float groundOrLine = 0.18f * (3.0f * std::sin(glm::radians(45.0f)) + 0.15f);
    EXPECT_GT(red, groundOrLine * 0.9f);
    EXPECT_LT(red, 0.60f * (3.0f * std::sin(glm::radians(45.0f)) + 0.15f));
    expectNotUniform(readPng(folder / "grid.png"));
    std::filesystem::remove_all(folder);
}

// Each tone mapping operator, chosen with --set, draws the same scene differently and is
// named in the capture's header; a manual exposure is recorded as 2^EV.
TEST(HeadlessRun, EveryToneMappingOperatorIsSelectableAndRecorded) {
    const auto folder = std::filesystem::temp_directory_path() / "firmament-operators-test";
    std::filesystem::remove_all(folder);
    std::vector<std::vector<std::uint8_t>> images;
    for (const std::string_view name : kToneMapOperatorNames) {
        const std::wstring wide(name.begin(), name.end());
        const auto png = folder / (L"op" + std::to_wstring(images.size()) + L".png");
        const ProcessResult run = captureHeadless({{},
                                                   {L"toneMapping.operator=" + wide, L"camera.pitch=-5", L"toneMapping.autoExposure=off",
                                                    L"toneMapping.exposure=-1.5", L"clouds.enabled=off", L"terrain.enabled=off"},
                                                   128, 96, 2, png});
        ASSERT_EQ(run.exitCode, 0u) << run.output;
        const ExrFile file = readExr(std::filesystem::path(png).replace_extension(".exr"));
        EXPECT_EQ(std::get<std::string>(file.attributes.at("firmament.toneMapping.operator")), name);
        EXPECT_NEAR(std::get<float>(file.attributes.at("firmament.toneMapping.exposure")), std::exp2(-1.5f), 1e-6f);
        EXPECT_FALSE(file.attributes.count("firmament.toneMapping.averageLuminance")) << "no measurement without auto exposure";
        images.push_back(readPng(png).pixels);
    }
    for (size_t a = 0; a < images.size(); ++a)
        for (size_t b = a + 1; b < images.size(); ++b)
            EXPECT_NE(images[a], images[b]) << kToneMapOperatorNames[a] << " and " << kToneMapOperatorNames[b] << " look the same";
    std::filesystem::remove_all(folder);
}

// Every GUI panel drawn headless and captured with --capture-ui: each capture differs from
// the same frame without the GUI, and the panels differ from each other.
TEST(HeadlessRun, EveryPanelIsDrawnAndCapturedWithCaptureUi) {
    const auto folder = std::filesystem::temp_directory_path() / "firmament-panels-test";
    std::filesystem::remove_all(folder);
    auto capture = [&](const std::wstring& name, std::vector<std::wstring> settings, bool gui) {
        settings.insert(settings.end(), {L"clouds.enabled=off", L"terrain.enabled=off"});  // a cheap scene
        HeadlessCapture c{nullptr, settings, 640, 480, 3, folder / (name + L".png")};
        c.captureUi = gui;
        const ProcessResult run = captureHeadless(c);
        EXPECT_EQ(run.exitCode, 0u) << run.output;
        return readPng(folder / (name + L".png"));
    };
    const Rgba8Image plain = capture(L"no-gui", {}, false);
    std::vector<Rgba8Image> panels;
    for (const wchar_t* panel : {L"basic", L"additional", L"tone mapping", L"performance"}) {
        panels.push_back(capture(std::wstring(L"panel-") + panel[0], {std::wstring(L"ui.panel=") + panel}, true));
        const Rgba8Image& withGui = panels.back();
        size_t differing = 0;
        for (size_t i = 0; i < plain.pixels.size(); ++i) differing += plain.pixels[i] != withGui.pixels[i];
        EXPECT_GT(differing, plain.pixels.size() / 50) << "panel " << std::string(panel, panel + wcslen(panel)) << " is not in the capture";
    }
    for (size_t a = 0; a < panels.size(); ++a)
        for (size_t b = a + 1; b < panels.size(); ++b) EXPECT_NE(panels[a].pixels, panels[b].pixels) << a << " and " << b;
    // The help window (F1, or ui.help) is drawn over the scene too.
    const Rgba8Image help = capture(L"help", {L"ui.help=on"}, true);
    EXPECT_NE(help.pixels, panels[0].pixels);
    std::filesystem::remove_all(folder);
}

// A recorded flight plays back headless over its whole length, and a run can record one.
TEST(HeadlessRun, PlaysAFlightAndRecordsOne) {
    const auto folder = std::filesystem::temp_directory_path() / "firmament-flight-run";
    std::filesystem::remove_all(folder);
    std::filesystem::create_directories(folder);
    std::ofstream(folder / "flight.json") << R"({"keyframes": [
        {"time": 0, "camera": {"position": [0, 4100, 0], "yaw": 0}},
        {"time": 0.5, "camera": {"position": [0, 2100, 1000], "yaw": 90}}],
        "captures": [{"time": 0, "name": "first"}, {"time": 0.25, "name": "middle"}, {"time": 0.5, "name": "last"}]})";
    const ProcessResult run =
        runProcess(firmamentExe(), withCheapScene({L"--headless", L"--resolution", L"64x64", L"--flight", (folder / "flight.json").wstring(),
                                                   L"--record-flight", (folder / "recorded.json").wstring(), L"--capture",
                                                   (folder / "end.png").wstring()}));
    ASSERT_EQ(run.exitCode, 0u) << run.output;
    EXPECT_NE(run.output.find("GPU time per pass over 31 frames"), std::string::npos) << run.output;  // 0.5 s at 60 Hz, both ends
    // The last frame is the last keyframe: the view matrix moves (0, 2100, 1000) to the origin.
    const glm::mat4 view = std::get<glm::mat4>(readExr(folder / "end.exr").attributes.at("firmament.view"));
    const glm::vec4 eye = view * glm::vec4(0.0f, 2100.0f, 1000.0f, 1.0f);
    EXPECT_NEAR(glm::length(glm::vec3(eye)), 0.0f, 1e-2f);
    // The flight's captures beside it, each of the first frame at or past its time: the first
    // frame shows time zero, the first keyframe (a fixed step's clock has already advanced one
    // step by then: the demo's sunrise was once its second frame), the middle one halfway
    // (t = 0.25 exactly), the last one the last keyframe's view.
    const glm::mat4 first = std::get<glm::mat4>(readExr(folder / "end-first.exr").attributes.at("firmament.view"));
    EXPECT_NEAR(glm::length(glm::vec3(first * glm::vec4(0.0f, 4100.0f, 0.0f, 1.0f))), 0.0f, 1e-2f);
    const glm::mat4 middle = std::get<glm::mat4>(readExr(folder / "end-middle.exr").attributes.at("firmament.view"));
    EXPECT_NEAR(glm::length(glm::vec3(middle * glm::vec4(0.0f, 3100.0f, 500.0f, 1.0f))), 0.0f, 1e-2f);
    EXPECT_EQ(std::get<glm::mat4>(readExr(folder / "end-last.exr").attributes.at("firmament.view")), view);
    EXPECT_NE(run.output.find("captured"), std::string::npos);
    // The recording holds the same path, ten keyframes a second.
    const auto recorded = nlohmann::json::parse(std::ifstream(folder / "recorded.json"));
    ASSERT_GE(recorded["keyframes"].size(), 5u);
    EXPECT_EQ(recorded["keyframes"].back()["camera"]["yaw"], 90.0);

    // With --time-step the flight is flown at that step (tools/demo's 10 frames a second): 0.5 s
    // in steps of 0.125 s is 5 frames, both ends, with the same views at the captures' times.
    const ProcessResult coarse =
        runProcess(firmamentExe(), withCheapScene({L"--headless", L"--resolution", L"64x64", L"--flight", (folder / "flight.json").wstring(),
                                                   L"--time-step", L"0.125", L"--capture", (folder / "coarse.png").wstring()}));
    ASSERT_EQ(coarse.exitCode, 0u) << coarse.output;
    EXPECT_NE(coarse.output.find("GPU time per pass over 5 frames"), std::string::npos) << coarse.output;
    EXPECT_EQ(std::get<glm::mat4>(readExr(folder / "coarse.exr").attributes.at("firmament.view")), view);
    EXPECT_EQ(std::get<glm::mat4>(readExr(folder / "coarse-middle.exr").attributes.at("firmament.view")), middle);
    EXPECT_EQ(std::get<glm::mat4>(readExr(folder / "coarse-first.exr").attributes.at("firmament.view")), first);
    std::filesystem::remove_all(folder);
}

// A flight of one keyframe is the way to save and share a view: it sets the camera and the sun
// exactly, at any time of its keyframe, and the log says what it is.
TEST(HeadlessRun, AOneKeyframeFlightSetsTheCameraAndSunExactly) {
    const auto folder = std::filesystem::temp_directory_path() / "firmament-still-view";
    std::filesystem::remove_all(folder);
    std::filesystem::create_directories(folder);
    for (const char* time : {"0", "2.5"}) {
        std::ofstream(folder / "view.json") << R"({"keyframes": [{"time": )" << time << R"(,
            "camera": {"position": [1200, 2600, -3400], "yaw": 135, "pitch": -12},
            "sun": {"elevation": 14, "azimuth": -150}}]})";
        const ProcessResult run =
            runProcess(firmamentExe(), withCheapScene({L"--headless", L"--resolution", L"64x64", L"--frames", L"3", L"--flight",
                                                       (folder / "view.json").wstring(), L"--capture", (folder / "view.png").wstring()}));
        ASSERT_EQ(run.exitCode, 0u) << run.output;
        EXPECT_NE(run.output.find("playing a still view (one keyframe)"), std::string::npos) << run.output;
        const auto settings = nlohmann::json::parse(std::get<std::string>(readExr(folder / "view.exr").attributes.at("firmament.settings")));
        EXPECT_EQ(settings["camera"]["position"], nlohmann::json::array({1200.0, 2600.0, -3400.0})) << "keyframe at " << time;
        EXPECT_EQ(settings["camera"]["yaw"], 135.0) << "keyframe at " << time;
        EXPECT_EQ(settings["camera"]["pitch"], -12.0) << "keyframe at " << time;
        EXPECT_EQ(settings["sun"]["elevation"], 14.0) << "keyframe at " << time;
        EXPECT_EQ(settings["sun"]["azimuth"], -150.0) << "keyframe at " << time;
    }
    std::filesystem::remove_all(folder);
}

// --hdr-float32, for measurement: the same frame as the half-float one, to half's rounding, and
// the light below half's smallest number (6e-8; the sky 15 degrees after sunset is mostly there)
// kept rather than lost. Hillaire's model: its tables and camera volumes are 32-bit floats too.
TEST(HeadlessRun, Float32CaptureKeepsTheLightHalfFloatsLose) {
    const auto folder = std::filesystem::temp_directory_path() / "firmament-float32-capture";
    std::filesystem::remove_all(folder);
    std::map<std::string, FloatExrFile> captures;
    for (const std::string precision : {"half", "float32"}) {
        std::vector<std::wstring> arguments{L"--headless", L"--frames", L"1", L"--resolution", L"64x40",
                                            L"--capture", (folder / (precision + ".png")).wstring(),
                                            L"--set", L"scene.orientationGrid=off", L"--set", L"lightShafts.enabled=off",
                                            L"--set", L"atmosphere.model=Hillaire 2020", L"--set", L"sun.elevation=-15",
                                            L"--set", L"camera.pitch=10", L"--set", L"camera.fieldOfView=90"};
        if (precision == "float32") arguments.push_back(L"--hdr-float32");
        const ProcessResult run = runProcess(firmamentExe(), withCheapScene(arguments));
        ASSERT_EQ(run.exitCode, 0u) << run.output;
        captures[precision] = readFloatExr(folder / (precision + ".exr"));
    }
    const std::vector<float>& half = captures["half"].image.rgba;
    const std::vector<float>& full = captures["float32"].image.rgba;
    ASSERT_EQ(half.size(), full.size());
    constexpr float kSmallestNormalHalf = 6.1035e-5f, kHalfSubnormalStep = 5.9605e-8f;
    size_t belowHalf = 0, channels = 0;
    for (size_t i = 0; i < full.size(); ++i) {
        if (i % 4 == 3) continue;  // alpha
        ++channels;
        ASSERT_TRUE(std::isfinite(full[i]) && full[i] >= 0.0f) << "value " << i << ": " << full[i];
        // Half keeps 11 significant bits of a normal number and a fixed step below them; the
        // conversion may round toward zero (wined3d's does), so one unit of the last place.
        const float bound = full[i] >= kSmallestNormalHalf ? full[i] / 1024.0f : kHalfSubnormalStep;
        EXPECT_LE(std::abs(half[i] - full[i]), bound * 1.01f) << "value " << i << ": half " << half[i] << ", float " << full[i];
        if (full[i] > 0.0f && full[i] < 0.5f * kHalfSubnormalStep) ++belowHalf;
    }
    std::printf("%zu of %zu channels hold light below half float's smallest number\n", belowHalf, channels);
    EXPECT_GT(belowHalf, channels / 4) << "the 32-bit capture holds no more than a half-float one would";
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
    // The default scene draws the terrain: its height field is read (the headless test's run
    // without it must not say so).
    EXPECT_TRUE(run.output.find("terrain: height field loaded") != std::string::npos || run.output.find("terrain: height field generated") != std::string::npos)
        << run.output;
    const Rgba8Image image = readPng(folder / "window.png");
    EXPECT_GT(image.width, 0);
    EXPECT_GT(image.height, 0);
    expectNotUniform(image);
    std::filesystem::remove_all(folder);
}

}  // namespace
}  // namespace firmament::test
