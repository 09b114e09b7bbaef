// Command-line parsing: values, defaults, and one clear message for each kind of bad input.
#include "app/CommandLine.h"

#include <gtest/gtest.h>

#include <algorithm>

namespace firmament {
namespace {

ParsedCommandLine parse(std::vector<std::string> args) { return parseCommandLine(args); }

void expectError(std::vector<std::string> args, const std::string& mustMention) {
    const ParsedCommandLine p = parse(args);
    EXPECT_FALSE(p.error.empty()) << "no error for " << args.front();
    EXPECT_NE(p.error.find(mustMention), std::string::npos) << "'" << p.error << "' should mention '" << mustMention << "'";
}

TEST(CommandLine, DefaultsAreAWindowOnTheHardwareAdapter) {
    const ParsedCommandLine p = parse({});
    ASSERT_TRUE(p.error.empty());
    EXPECT_FALSE(p.options.headless);
    EXPECT_EQ(p.options.driver, DriverType::Hardware);
    EXPECT_EQ(p.options.width, 1280);
    EXPECT_EQ(p.options.height, 720);
    EXPECT_FALSE(p.options.vsync.has_value());  // the settings decide (display.vsync, on by default)
    EXPECT_FALSE(p.options.captureUi);
    EXPECT_EQ(p.options.shaderCompiler, "auto");
    EXPECT_EQ(p.options.stateFile, std::filesystem::path("firmament-state.json"));
    EXPECT_EQ(p.options.frameCount(), 0);  // until the window is closed
}

TEST(CommandLine, HeadlessUsesWarpAndRendersThirtyFramesByDefault) {
    const ParsedCommandLine p = parse({"--headless"});
    ASSERT_TRUE(p.error.empty());
    EXPECT_EQ(p.options.driver, DriverType::Warp);
    EXPECT_EQ(p.options.frameCount(), 30);
    EXPECT_EQ(parse({"--headless", "--hardware"}).options.driver, DriverType::Hardware);
    EXPECT_EQ(parse({"--headless", "--adapter", "1"}).options.driver, DriverType::Hardware);
}

TEST(CommandLine, ParsesEveryValueInBothSpellings) {
    const ParsedCommandLine p = parse({"--frames", "12", "--resolution=320x180", "--vsync", "off", "--capture=out/a.png",
                                       "--shader-dir", "s", "--adapter=2", "--capture-ui", "--shader-compiler", "vkd3d",
                                       "--shader-source=src", "--settings", "a.json", "--set", "camera.yaw=90",
                                       "--set=sun.elevation=10", "--state-file", "b.json"});
    ASSERT_TRUE(p.error.empty()) << p.error;
    EXPECT_EQ(p.options.frameCount(), 12);
    EXPECT_EQ(p.options.width, 320);
    EXPECT_EQ(p.options.height, 180);
    EXPECT_FALSE(*p.options.vsync);
    EXPECT_TRUE(p.options.captureUi);
    EXPECT_EQ(p.options.shaderCompiler, "vkd3d");
    EXPECT_EQ(*p.options.shaderSource, std::filesystem::path("src"));
    EXPECT_EQ(*p.options.settingsFile, std::filesystem::path("a.json"));
    EXPECT_EQ(p.options.stateFile, std::filesystem::path("b.json"));
    EXPECT_EQ(p.options.assignments, (std::vector<std::string>{"camera.yaw=90", "sun.elevation=10"}));
    EXPECT_EQ(p.options.capturePng(), std::filesystem::path("out/a.png"));
    EXPECT_EQ(p.options.captureExr(), std::filesystem::path("out/a.exr"));
    EXPECT_EQ(*p.options.shaderDir, std::filesystem::path("s"));
    EXPECT_EQ(*p.options.adapter, 2u);
}

TEST(CommandLine, BadInputNamesTheProblem) {
    expectError({"--fly-to-the-moon"}, "unknown option '--fly-to-the-moon'");
    expectError({"--resolution", "1280"}, "WIDTHxHEIGHT");
    expectError({"--resolution", "axb"}, "WIDTHxHEIGHT");
    expectError({"--resolution", "1280x-5"}, "out of range");
    expectError({"--resolution", "8x8"}, "out of range");
    expectError({"--resolution", "99999x720"}, "out of range");
    expectError({"--frames", "0"}, "--frames");
    expectError({"--frames", "ten"}, "--frames");
    expectError({"--frames"}, "needs a value");
    expectError({"--capture", "shot.jpg"}, ".png or .exr");
    expectError({"--vsync", "maybe"}, "'on' or 'off'");
    expectError({"--adapter", "-1"}, "adapter index");
    expectError({"--headless=yes"}, "takes no value");
    expectError({"--warp", "--hardware"}, "exclude each other");
    expectError({"--warp", "--adapter", "0"}, "exclude each other");
    expectError({"--shader-compiler", "gcc"}, "not one of auto, d3dcompile, vkd3d, fxc, none");
    expectError({"--set", "fieldOfView=60"}, "section.key=value");
    expectError({"--set", "camera.fieldOfView"}, "section.key=value");
    expectError({"--settings", ""}, "the path is empty");
    expectError({"--capture-ui=yes"}, "takes no value");
    expectError({"--simulate-device-loss", "0"}, "--simulate-device-loss: '0' is not a frame number");
    expectError({"--simulate-device-loss", "soon"}, "is not a frame number");
}

TEST(CommandLine, TimeStepTakesSecondsFromZeroToOne) {
    EXPECT_FALSE(parse({}).options.timeStep.has_value());
    EXPECT_EQ(parse({"--time-step", "0"}).options.timeStep, 0.0);
    EXPECT_EQ(parse({"--time-step=0.5"}).options.timeStep, 0.5);
    expectError({"--time-step", "-0.1"}, "--time-step: '-0.1' is not a number of seconds from 0 to 1");
    expectError({"--time-step", "2"}, "is not a number of seconds from 0 to 1");
    expectError({"--time-step", "soon"}, "is not a number of seconds");
    expectError({"--time-step", "nan"}, "is not a number of seconds");
    expectError({"--time-step"}, "--time-step needs a value");
}

TEST(CommandLine, SimulatedDeviceLossTakesAFrameNumber) {
    EXPECT_FALSE(parse({}).options.simulateDeviceLoss.has_value());
    EXPECT_EQ(parse({"--simulate-device-loss", "12"}).options.simulateDeviceLoss, 12);
    EXPECT_EQ(parse({"--simulate-device-loss=3"}).options.simulateDeviceLoss, 3);
}

// The table drives both: every option of it is in the usage text, with its value's placeholder,
// and the parser takes it (with its example value, in both spellings), and the usage text names
// no option the table lacks.
TEST(CommandLine, TheOptionTableDrivesTheParserAndTheUsage) {
    const std::string usage = usageText();
    const std::vector<CommandLineOption> options = commandLineOptions();
    ASSERT_GE(options.size(), 30u);
    for (const CommandLineOption& option : options) {
        const std::string head = option.value.empty() ? option.name : option.name + " " + option.value;
        EXPECT_NE(usage.find("  " + head), std::string::npos) << head;
        // Taken with its example: no error of its own (an option that needs another, as
        // --soak-report needs --soak, may still say so).
        auto takes = [&](const std::vector<std::string>& arguments) {
            const std::string error = parse(arguments).error;
            const bool own = error.rfind("unknown option", 0) == 0 || error.rfind(option.name + ":", 0) == 0 ||
                             error.rfind(option.name + " needs a value", 0) == 0 || error.rfind(option.name + " takes no value", 0) == 0;
            EXPECT_FALSE(own) << arguments.front() << ": " << error;
        };
        if (option.value.empty()) {
            takes({option.name});
            expectError({option.name + "=1"}, option.name + " takes no value");
        } else {
            takes({option.name, option.example});
            takes({option.name + "=" + option.example});
            expectError({option.name}, option.name + " needs a value");
        }
    }
    // Every "--word" at the start of a usage line is an option of the table.
    size_t line = 0;
    int listed = 0;
    while ((line = usage.find("\n  --", line)) != std::string::npos) {
        line += 3;
        const std::string name = usage.substr(line, usage.find_first_of(" ,\n", line) - line);
        EXPECT_TRUE(std::any_of(options.begin(), options.end(), [&](const CommandLineOption& o) { return o.name == name; })) << name;
        ++listed;
    }
    EXPECT_EQ(listed, static_cast<int>(options.size()));
    for (const char* option : {"--warp", "--hardware", "--adapter", "--headless", "--frames", "--resolution", "--vsync",
                               "--capture", "--capture-ui", "--settings", "--set", "--state-file", "--shader-dir",
                               "--shader-source", "--shader-compiler", "--benchmark", "--benchmark-output", "--generate-cloud-scattering", "--generate-deck-diffusion",
                               "--simulate-device-loss", "--time-step", "--batch", "--soak", "--soak-report", "--flight",
                               "--record-flight", "--export-luts", "--cache-dir", "--no-cache", "--version", "--help"})
        EXPECT_NE(usage.find(option), std::string::npos) << option;
    EXPECT_TRUE(parse({"-h"}).options.help);
    EXPECT_TRUE(parse({"/?"}).options.help);
}

TEST(CommandLine, AtmosphereTableOptions) {
    const ParsedCommandLine p = parse({"--export-luts", "tables", "--cache-dir", "cache"});
    ASSERT_TRUE(p.error.empty()) << p.error;
    EXPECT_EQ(p.options.exportLuts, std::filesystem::path("tables"));
    EXPECT_EQ(p.options.cacheDir, std::filesystem::path("cache"));
    EXPECT_FALSE(p.options.noCache);
    EXPECT_TRUE(parse({"--no-cache"}).options.noCache);
    expectError({"--export-luts"}, "--export-luts");
    expectError({"--export-luts", ""}, "empty");
    expectError({"--no-cache=yes"}, "--no-cache");
}

TEST(CommandLine, CloudScatteringGenerator) {
    const ParsedCommandLine p = parse({"--generate-cloud-scattering", "table.exr"});
    ASSERT_TRUE(p.error.empty()) << p.error;
    EXPECT_EQ(p.options.generateCloudScattering, std::filesystem::path("table.exr"));
    EXPECT_FALSE(parse({}).options.generateCloudScattering);
    expectError({"--generate-cloud-scattering"}, "--generate-cloud-scattering");
    expectError({"--generate-cloud-scattering", ""}, "empty");
    EXPECT_EQ(parse({"--generate-deck-diffusion", "deck.exr"}).options.generateDeckDiffusion, std::filesystem::path("deck.exr"));
    EXPECT_FALSE(parse({}).options.generateDeckDiffusion);
    expectError({"--generate-deck-diffusion"}, "--generate-deck-diffusion");
}

// A benchmark runs headless on WARP (unless told otherwise) and takes its views and frame
// counts from its file.
TEST(CommandLine, BenchmarkOptions) {
    const ParsedCommandLine p = parse({"--benchmark", "scenarios.json", "--benchmark-output", "out/results.json"});
    ASSERT_TRUE(p.error.empty()) << p.error;
    EXPECT_EQ(p.options.benchmark, std::filesystem::path("scenarios.json"));
    EXPECT_EQ(p.options.benchmarkResults(), std::filesystem::path("out/results.json"));
    EXPECT_TRUE(p.options.headless);
    EXPECT_EQ(p.options.driver, DriverType::Warp);
    EXPECT_EQ(parse({"--benchmark", "b.json"}).options.benchmarkResults(), std::filesystem::path("benchmark-results.json"));
    EXPECT_EQ(parse({"--benchmark", "b.json", "--hardware"}).options.driver, DriverType::Hardware);
    expectError({"--benchmark", "b.json", "--frames", "3"}, "--benchmark takes its views");
    expectError({"--benchmark", "b.json", "--capture", "x.png"}, "--benchmark takes its views");
    expectError({"--benchmark", "b.json", "--flight", "f.json"}, "--benchmark takes its views");
    expectError({"--benchmark-output", "r.json"}, "--benchmark-output needs --benchmark");
    expectError({"--benchmark", ""}, "empty");
}

TEST(CommandLine, SoakOptions) {
    const ParsedCommandLine p = parse({"--headless", "--soak", "media/soak/schedule.json", "--soak-report", "out/soak.json"});
    ASSERT_TRUE(p.error.empty()) << p.error;
    EXPECT_EQ(p.options.soak, std::filesystem::path("media/soak/schedule.json"));
    EXPECT_EQ(p.options.soakResults(), std::filesystem::path("out/soak.json"));
    EXPECT_EQ(p.options.frameCount(), 10000);  // a soak's default length, headless or not
    EXPECT_EQ(parse({"--soak", "s.json"}).options.frameCount(), 10000);
    EXPECT_EQ(parse({"--soak", "s.json", "--frames", "1000"}).options.frameCount(), 1000);
    EXPECT_EQ(parse({"--soak", "s.json"}).options.soakResults(), std::filesystem::path("soak-report.json"));
    expectError({"--soak-report", "r.json"}, "--soak-report needs --soak");
    expectError({"--soak", "s.json", "--benchmark", "b.json"}, "--soak and --benchmark exclude each other");
    expectError({"--soak", ""}, "--soak: the path is empty");
}

}  // namespace
}  // namespace firmament
