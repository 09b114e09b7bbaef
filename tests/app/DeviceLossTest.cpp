// A lost Direct3D device (DXGI_ERROR_DEVICE_REMOVED or _RESET from Present, or a device that
// reports itself removed) is answered by making every GPU resource again: the device, shaders,
// swap chain, renderer with its techniques and tables (from the cache), and the GUI. The
// settings, camera and clock are kept. --simulate-device-loss N takes that path after frame N.
#include "core/ExrImage.h"
#include "core/PngImage.h"
#include "support/Process.h"
#include "support/TestPaths.h"

#include <gtest/gtest.h>

#include <cstdlib>
#include <string>
#include <vector>

namespace firmament::test {
namespace {

struct CapturedRun {
    ProcessResult process;
    Rgba8Image image;
    std::string settings;  // the capture's firmament.settings attribute: the state at the end
};

// Six headless frames of the default scene (atmosphere, terrain, shadows, light shafts, clouds),
// captured after the last; `extra` arguments added.
CapturedRun capture(const std::string& name, const std::vector<std::wstring>& extra) {
    const auto folder = std::filesystem::temp_directory_path() / ("firmament-device-loss-" + name);
    std::filesystem::remove_all(folder);
    std::vector<std::wstring> arguments{L"--headless", L"--frames", L"6", L"--resolution", L"192x108", L"--set", L"sun.elevation=12",
                                        L"--capture", (folder / "frame.png").wstring()};
    arguments.insert(arguments.end(), extra.begin(), extra.end());
    CapturedRun run{runProcess(firmamentExe(), arguments), {}, {}};
    if (run.process.exitCode == 0) {
        run.image = readPng(folder / "frame.png");
        const ExrFile exr = readExr(folder / "frame.exr");
        if (const auto it = exr.attributes.find("firmament.settings"); it != exr.attributes.end())
            run.settings = std::get<std::string>(it->second);
    }
    std::filesystem::remove_all(folder);
    return run;
}

TEST(DeviceLoss, ASimulatedLossMakesEverythingAgainAndTheFramesGoOnUnchanged) {
    const CapturedRun reference = capture("reference", {});
    ASSERT_EQ(reference.process.exitCode, 0u) << reference.process.output;
    const CapturedRun lost = capture("lost", {L"--simulate-device-loss", L"3"});
    ASSERT_EQ(lost.process.exitCode, 0u) << lost.process.output;
    EXPECT_NE(lost.process.output.find("the Direct3D device was lost after frame 3 (DXGI_ERROR_DEVICE_REMOVED, simulated"),
              std::string::npos)
        << lost.process.output;
    EXPECT_NE(lost.process.output.find("device recreated in"), std::string::npos) << lost.process.output;
    EXPECT_EQ(reference.process.output.find("device recreated"), std::string::npos) << reference.process.output;

    // The settings, camera and sun are kept: the capture's state is the reference's, key for key.
    ASSERT_FALSE(reference.settings.empty());
    EXPECT_EQ(lost.settings, reference.settings);
    // The frames after the loss are the frames without it: every technique was made again from
    // the same state and the same clock. Within one 8-bit step.
    ASSERT_EQ(lost.image.pixels.size(), reference.image.pixels.size());
    int worst = 0;
    size_t differing = 0;
    for (size_t i = 0; i < lost.image.pixels.size(); ++i) {
        const int d = std::abs(static_cast<int>(lost.image.pixels[i]) - static_cast<int>(reference.image.pixels[i]));
        worst = std::max(worst, d);
        differing += d > 0;
    }
    EXPECT_LE(worst, 1) << differing << " channel values differ";
    std::printf("after a simulated device loss: largest difference %d/255, %zu channel values differ\n", worst, differing);
}

TEST(DeviceLoss, ABadFrameNumberIsRefused) {
    const ProcessResult run = runProcess(firmamentExe(), {L"--headless", L"--simulate-device-loss", L"0"});
    EXPECT_EQ(run.exitCode, 2u) << run.output;
    EXPECT_NE(run.output.find("--simulate-device-loss: '0' is not a frame number"), std::string::npos) << run.output;
}

}  // namespace
}  // namespace firmament::test
