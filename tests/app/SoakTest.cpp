// The short soak (tools/soak runs the long one): 1,000 headless frames at 160x90, flying the
// demo flight in a loop while the shipped schedule flips every toggle and mode, four loops of
// 240 frames. After the three warm-up loops neither the live Direct3D 11 objects, nor the
// handles, nor the private memory may grow beyond the schedule's bounds; and the counts are real
// ones (a scene of this size holds hundreds of objects).
#include "support/Process.h"
#include "support/TestPaths.h"

#include <nlohmann/json.hpp>

#include <gtest/gtest.h>

#include <fstream>

namespace firmament::test {
namespace {

TEST(Soak, AThousandFramesOfEveryToggleAndModeGrowNothing) {
    const auto folder = std::filesystem::temp_directory_path() / "firmament-soak";
    std::filesystem::remove_all(folder);
    std::filesystem::create_directories(folder);
    const auto media = executableFolder() / "media";
    const ProcessResult run = runProcess(firmamentExe(), {L"--headless", L"--resolution", L"160x90", L"--frames", L"1000", L"--soak",
                                                          (media / "soak" / "schedule.json").wstring(), L"--soak-report",
                                                          (folder / "report.json").wstring(), L"--flight",
                                                          (media / "flights" / "demo.json").wstring()});
    ASSERT_EQ(run.exitCode, 0u) << run.output;
    EXPECT_NE(run.output.find("soak: passed"), std::string::npos) << run.output;
    nlohmann::json report;
    {
        std::ifstream in(folder / "report.json");  // closed before the folder is removed (Windows)
        report = nlohmann::json::parse(in);
    }
    ASSERT_EQ(report["samples"].size(), 4u);  // at frames 240, 480, 720 and 960
    EXPECT_EQ(report["passed"], true);
    for (const nlohmann::json& sample : report["samples"]) {
        EXPECT_GT(sample["liveObjects"].get<long>(), 100) << sample.dump();
        EXPECT_GT(sample["liveObjectsByKind"]["textures"].get<long>(), 10) << sample.dump();
        EXPECT_GT(sample["liveObjectsByKind"]["shaders"].get<long>(), 10) << sample.dump();
        EXPECT_GT(sample["handles"].get<long>(), 0) << sample.dump();
        EXPECT_GT(sample["privateBytes"].get<double>(), 32.0 * 1024 * 1024) << sample.dump();
    }
    std::printf("%s\n", report["growth"].dump(2).c_str());
    std::filesystem::remove_all(folder);
}

}  // namespace
}  // namespace firmament::test
