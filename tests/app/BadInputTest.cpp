// Bad input to firmament.exe: a message that names the problem and a non-zero exit code
// (2 for the command line, 1 for what is found at run time), never a crash.
#include "support/Process.h"
#include "support/TestPaths.h"

#include <gtest/gtest.h>

#include <fstream>

namespace firmament::test {
namespace {

void expectFailure(const std::vector<std::wstring>& arguments, unsigned long exitCode, const std::string& message) {
    const ProcessResult run = runProcess(firmamentExe(), arguments);
    EXPECT_EQ(run.exitCode, exitCode) << run.output;
    EXPECT_NE(run.output.find("error: "), std::string::npos) << run.output;
    EXPECT_NE(run.output.find(message), std::string::npos) << "expected '" << message << "' in: " << run.output;
}

TEST(BadInput, UnknownOption) { expectFailure({L"--headless", L"--bogus"}, 2, "unknown option '--bogus'"); }

TEST(BadInput, MalformedResolution) {
    expectFailure({L"--headless", L"--resolution", L"1920by1080"}, 2, "--resolution: '1920by1080' is not WIDTHxHEIGHT");
    expectFailure({L"--headless", L"--resolution", L"4x4"}, 2, "out of range");
}

TEST(BadInput, UnwritableCapturePath) {
    // The capture's folder would have to be created inside a regular file.
    const auto blocker = std::filesystem::temp_directory_path() / "firmament-blocker-file";
    std::ofstream(blocker) << "not a folder";
    expectFailure({L"--headless", L"--frames", L"1", L"--capture", (blocker / L"shot.png").wstring()}, 1,
                  "firmament-blocker-file");
    std::filesystem::remove(blocker);
}

TEST(BadInput, CaptureWithAnUnknownExtension) {
    expectFailure({L"--headless", L"--capture", L"shot.bmp"}, 2, "must end in .png or .exr");
}

TEST(BadInput, BatchNeedsItsCapturePathAndAGoodViewsFile) {
    expectFailure({L"--batch", L"views.json"}, 2, "--batch views.json writes each view to --capture's PATH-name.png");
    expectFailure({L"--batch", L"-", L"--capture", L"x.png"}, 2, "--batch - takes each capture's path from its request");
    expectFailure({L"--batch", L"-", L"--benchmark", L"b.json"}, 2, "leave out --benchmark");
    const auto folder = std::filesystem::temp_directory_path() / "firmament-bad-batch";
    std::filesystem::create_directories(folder);
    expectFailure({L"--batch", (folder / "missing.json").wstring(), L"--capture", (folder / "x.png").wstring()}, 2, "missing.json");
    std::ofstream(folder / "twice.json") << R"({"views": [{"name": "a"}, {"name": "a"}]})";
    expectFailure({L"--batch", (folder / "twice.json").wstring(), L"--capture", (folder / "x.png").wstring()}, 2,
                  "views[1].name: 'a' is used twice");
    std::filesystem::remove_all(folder);
}

TEST(BadInput, MissingShaderFolder) {
    expectFailure({L"--headless", L"--frames", L"1", L"--shader-dir", L"no-such-folder"}, 1,
                  "shader folder 'no-such-folder' does not exist");
}

TEST(BadInput, ShaderFolderWithoutManifest) {
    const auto folder = std::filesystem::temp_directory_path() / "firmament-empty-shaders";
    std::filesystem::create_directories(folder);
    expectFailure({L"--headless", L"--frames", L"1", L"--shader-dir", folder.wstring()}, 1, "has no manifest.txt");
    std::filesystem::remove_all(folder);
}

TEST(BadInput, SettingsOnTheCommandLineNameTheKey) {
    expectFailure({L"--headless", L"--set", L"camera.fieldOfVeiw=60"}, 2, "--set camera.fieldOfVeiw=60: unknown key 'camera.fieldOfVeiw'");
    expectFailure({L"--headless", L"--set", L"camera.fieldOfView=wide"}, 2, "camera.fieldOfView: expected a number, got 'wide'");
    expectFailure({L"--headless", L"--set", L"camera.fieldOfView=500"}, 2, "camera.fieldOfView: 500 is outside 10 to 120");
    expectFailure({L"--headless", L"--set", L"fieldOfView"}, 2, "is not section.key=value");
}

TEST(BadInput, SettingsFilesNameTheKey) {
    const auto folder = std::filesystem::temp_directory_path() / "firmament-bad-settings";
    std::filesystem::create_directories(folder);
    std::ofstream(folder / "type.json") << R"({"sun": {"elevation": "high"}})";
    expectFailure({L"--headless", L"--settings", (folder / "type.json").wstring()}, 2, "sun.elevation: expected a number, got \"high\"");
    std::ofstream(folder / "syntax.json") << R"({"sun": {"elevation": 10)";
    expectFailure({L"--headless", L"--settings", (folder / "syntax.json").wstring()}, 2, "syntax.json: not valid JSON");
    expectFailure({L"--headless", L"--settings", (folder / "absent.json").wstring()}, 2, "absent.json");
    std::filesystem::remove_all(folder);
}

TEST(BadInput, ShaderCompilerAndSourceFolder) {
    expectFailure({L"--headless", L"--shader-compiler", L"cl"}, 2, "--shader-compiler: 'cl' is not one of");
    expectFailure({L"--headless", L"--frames", L"1", L"--shader-source", L"no-such-hlsl"}, 1,
                  "--shader-source: 'no-such-hlsl' is not a folder");
}

TEST(BadInput, SoakSchedules) {
    const auto folder = std::filesystem::temp_directory_path() / "firmament-bad-soak";
    std::filesystem::create_directories(folder);
    std::ofstream(folder / "step.json") << R"({"loopFrames": 10, "steps": [{"frame": 3, "set": ["clouds.enabled=maybe"]}]})";
    expectFailure({L"--headless", L"--soak", (folder / "step.json").wstring()}, 2, "step.json: steps[0].set: clouds.enabled=maybe: clouds.enabled: expected on or off");
    std::ofstream(folder / "short.json") << R"({"loopFrames": 10, "warmupLoops": 2})";
    expectFailure({L"--headless", L"--frames", L"20", L"--soak", (folder / "short.json").wstring()}, 2,
                  "the schedule needs at least 30 frames (3 loops of 10), and --frames is 20");
    expectFailure({L"--headless", L"--soak-report", L"r.json"}, 2, "--soak-report needs --soak");
    std::filesystem::remove_all(folder);
}

TEST(GoodInput, HelpAndVersionExitWithZero) {
    const ProcessResult help = runProcess(firmamentExe(), {L"--help"});
    EXPECT_EQ(help.exitCode, 0u);
    EXPECT_NE(help.output.find("Usage: firmament"), std::string::npos) << help.output;
    const ProcessResult version = runProcess(firmamentExe(), {L"--version"});
    EXPECT_EQ(version.exitCode, 0u);
    EXPECT_NE(version.output.find("firmament 0."), std::string::npos) << version.output;
}

}  // namespace
}  // namespace firmament::test
