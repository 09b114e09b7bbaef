// The batch of captures (--batch) against fresh processes: each golden view captured in one
// batch, in the file's order (so each view starts after others have run), is bit for bit the
// capture of its own firmament.exe, PNG and EXR; the views a test process asks for over
// standard input (--batch -) are answered in order, a refused one without ending the program.
#include "core/ExrImage.h"
#include "core/PngImage.h"
#include "support/ImageComparison.h"
#include "support/Process.h"
#include "support/TestPaths.h"

#include <gtest/gtest.h>
#include <nlohmann/json.hpp>

#include <chrono>
#include <fstream>
#include <string>

namespace firmament::test {
namespace {

nlohmann::json goldenViews() {
    std::ifstream in(executableFolder() / "golden" / "views.json");
    return nlohmann::json::parse(in, nullptr, /*allow_exceptions=*/false);
}

// Full tier (two minutes and a half: 31 views twice).
TEST(BatchCapture, EveryGoldenViewIsBitIdenticalToItsOwnProcess) {
    const nlohmann::json views = goldenViews();
    ASSERT_TRUE(views.is_object() && views["views"].is_array());
    const auto folder = std::filesystem::temp_directory_path() / "firmament-batch-identity";
    std::filesystem::remove_all(folder);
    std::filesystem::create_directories(folder);
    const ProcessResult batch = runProcess(firmamentExe(), {L"--batch", (executableFolder() / "golden" / "views.json").wstring(), L"--capture",
                                                            (folder / "batch.png").wstring()});
    ASSERT_EQ(batch.exitCode, 0u) << batch.output;

    const std::wstring resolution = std::to_wstring(views["resolution"][0].get<int>()) + L"x" + std::to_wstring(views["resolution"][1].get<int>());
    for (const auto& view : views["views"]) {
        const std::string name = view["name"];
        SCOPED_TRACE(name);
        std::ofstream(folder / (name + ".json")) << view["settings"].dump(2);
        const ProcessResult own = runProcess(firmamentExe(), {L"--headless", L"--frames", std::to_wstring(views["frames"].get<int>()), L"--resolution",
                                                              resolution, L"--settings", (folder / (name + ".json")).wstring(), L"--capture",
                                                              (folder / ("own-" + name + ".png")).wstring()});
        ASSERT_EQ(own.exitCode, 0u) << own.output;
        const Rgba8Image fromBatch = readPng(folder / ("batch-" + name + ".png"));
        const Rgba8Image fromOwn = readPng(folder / ("own-" + name + ".png"));
        const golden::Comparison c = golden::compare(fromBatch, fromOwn);
        EXPECT_EQ(c.differingPixels, 0u) << name << ": the batch's capture differs from its own process's: largest difference " << c.maxDifference
                                         << " at (" << c.worstPixel.x << ", " << c.worstPixel.y << ")";
        EXPECT_EQ(readExr(folder / ("batch-" + name + ".exr")).image.halfBits, readExr(folder / ("own-" + name + ".exr")).image.halfBits)
            << name << ": the radiance differs";
    }
    std::filesystem::remove_all(folder);
}

TEST(BatchCapture, RequestsAreAnsweredInOrderAndARefusedOneDoesNotEndTheProgram) {
    const auto folder = std::filesystem::temp_directory_path() / "firmament-batch-requests";
    std::filesystem::remove_all(folder);
    std::filesystem::create_directories(folder);
    RunningProcess program(firmamentExe(), {L"--batch", L"-", L"--set", L"clouds.enabled=off", L"--set", L"terrain.enabled=off"}, InputPipe::Yes);
    const std::string png = (folder / "sky.png").string();
    const nlohmann::json bad = {{"id", "bad"}, {"set", {"sun.elevation=high"}}, {"capture", png}};
    const nlohmann::json good = {{"id", "good"}, {"resolution", {32, 18}}, {"frames", 2}, {"capture", png}};
    ASSERT_TRUE(program.writeInput(bad.dump() + "\n"));  // JSON escapes the path's backslashes
    ASSERT_TRUE(program.writeInput(good.dump() + "\n"));
    program.closeInput();
    const auto exit = program.waitForExit(std::chrono::minutes(5));
    ASSERT_TRUE(exit.has_value()) << program.output();
    EXPECT_EQ(*exit, 0u) << program.output();
    const std::string output = program.output();
    const size_t refused = output.find("batch: refused bad: request 'bad': settings"), done = output.find("batch: done good");
    EXPECT_NE(refused, std::string::npos) << output;
    EXPECT_NE(done, std::string::npos) << output;
    EXPECT_LT(refused, done) << output;
    const Rgba8Image image = readPng(png);
    EXPECT_EQ(image.width, 32);
    EXPECT_EQ(image.height, 18);
    std::filesystem::remove_all(folder);
}

}  // namespace
}  // namespace firmament::test
