// firmament.exe: parses the command line, runs the App, and turns every error into one
// message and a non-zero exit code (1 runtime error, 2 bad command line or settings).
#include "app/App.h"
#include "app/BenchmarkPlan.h"
#include "app/CaptureBatch.h"
#include "app/CommandLine.h"
#include "app/FlightPath.h"
#include "app/SoakSchedule.h"
#include "clouds/DeckDiffusionTable.h"
#include "clouds/ParticleScattering.h"
#include "settings/State.h"
#include "core/Error.h"
#include "core/Log.h"
#include "FirmamentVersion.h"

#include <shellapi.h>
#include <windows.h>

#include <cstdio>
#include <exception>
#include <filesystem>
#include <functional>
#include <string>
#include <vector>

namespace {

std::vector<std::string> commandLineArguments() {
    int count = 0;
    wchar_t** wide = CommandLineToArgvW(GetCommandLineW(), &count);
    std::vector<std::string> arguments;
    for (int i = 1; i < count; ++i) arguments.push_back(firmament::narrow(wide[i]));
    LocalFree(wide);
    return arguments;
}

// --generate-cloud-scattering and --generate-deck-diffusion: one of the clouds' tables computed on
// the CPU with its progress logged, written to `path`; the exit code.
int generateTable(const std::string& what, const std::string& progressName, const std::filesystem::path& path,
                  const std::function<void(const std::function<void(double)>&, const std::filesystem::path&)>& make) {
    using namespace firmament;
    try {
        log::info("clouds: computing " + what);
        make([&](double progress) { log::info("clouds: " + progressName + " " + std::to_string(static_cast<int>(progress * 100.0 + 0.5)) + "%"); },
             path);
        log::info("clouds: wrote " + path.string());
        return 0;
    } catch (const Error& e) {
        log::error(e.what());
        return 1;
    }
}

}  // namespace

int main() {
    using namespace firmament;
    const ParsedCommandLine parsed = parseCommandLine(commandLineArguments());
    if (!parsed.error.empty()) {
        log::error(parsed.error + " (firmament --help lists the options)");
        return 2;
    }
    if (parsed.options.help) {
        std::fputs(usageText().c_str(), stdout);
        return 0;
    }
    if (parsed.options.version) {
        std::printf("firmament %s\n", kFirmamentVersion);
        return 0;
    }
    if (parsed.options.generateCloudScattering) {
        const ParticleScatteringParameters parameters;
        return generateTable("the particle's scattering table: " + parameters.describe(), "scattering table", *parsed.options.generateCloudScattering,
                             [&](const std::function<void(double)>& progress, const std::filesystem::path& path) {
                                 writeParticleScattering(path, computeParticleScattering(parameters, progress));
                             });
    }
    if (parsed.options.generateDeckDiffusion) {
        const DeckDiffusionParameters parameters;
        return generateTable("deck diffusion's table: " + parameters.describe(), "deck diffusion", *parsed.options.generateDeckDiffusion,
                             [&](const std::function<void(double)>& progress, const std::filesystem::path& path) {
                                 writeDeckDiffusion(path, computeDeckDiffusion(parameters, progress));
                             });
    }
    State state;
    std::optional<FlightPath> flight;
    std::optional<BenchmarkPlan> benchmark;
    std::optional<SoakSchedule> soak;
    std::optional<CaptureDefaults> batchDefaults;
    std::vector<CaptureItem> batch;
    try {
        if (parsed.options.flight) flight = FlightPath::load(*parsed.options.flight);
        if (parsed.options.settingsFile) loadStateFile(state, *parsed.options.settingsFile);
        if (parsed.options.vsync) state.display.vsync = *parsed.options.vsync;
        applyAssignments(state, parsed.options.assignments);
        if (parsed.options.benchmark) benchmark = loadBenchmarkPlan(*parsed.options.benchmark, state);
        if (parsed.options.batch) {
            batchDefaults = CaptureDefaults{state, parsed.options.width, parsed.options.height, parsed.options.frameCount(),
                                            parsed.options.captureUi, parsed.options.capture.value_or(std::filesystem::path())};
            if (*parsed.options.batch != "-") batch = loadCaptureBatch(*parsed.options.batch, *batchDefaults);
        }
        if (parsed.options.soak) {
            soak = SoakSchedule::load(*parsed.options.soak);
            if (parsed.options.frameCount() == 0 || parsed.options.frameCount() < soak->framesNeeded())
                throw Error("--soak " + parsed.options.soak->string() + ": the schedule needs at least " + std::to_string(soak->framesNeeded()) +
                            " frames (" + std::to_string(soak->samplesNeeded()) + " loops of " + std::to_string(soak->loopFrames) +
                            "), and --frames is " + std::to_string(parsed.options.frameCount()));
        }
    } catch (const Error& e) {  // bad settings are bad input, like a bad command line
        log::error(e.what());
        return 2;
    }
    try {
        App app(parsed.options, state, std::move(flight), std::move(soak));
        if (benchmark) return app.runBenchmark(*benchmark);
        if (batchDefaults) return *parsed.options.batch == "-" ? app.serveCaptures(*batchDefaults) : app.runBatch(batch);
        return app.run();
    } catch (const Error& e) {
        log::error(e.what());
    } catch (const std::exception& e) {
        log::error(std::string("unexpected failure: ") + e.what());
    }
    return 1;
}
