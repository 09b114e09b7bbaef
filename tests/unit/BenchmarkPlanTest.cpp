// The benchmark's scenario files and its statistics: views x variants x resolutions expand in
// order with each fragment applied over the last; every malformed file is refused with a message
// naming the field; the median is the middle sample (the mean of the two middle ones for an
// even count); the ratios divide the numerator variant's medians by the denominator's; every
// scenario file the program ships loads.
#include "app/BenchmarkPlan.h"
#include "app/BenchmarkReport.h"
#include "core/SettingsJson.h"
#include "support/TestPaths.h"

#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>

#include <string>

namespace firmament {
namespace {

using nlohmann::json;

json plan() {
    return json::parse(R"json({
      "format": 1, "name": "test", "warmupFrames": 2, "measuredFrames": 4, "tables": true,
      "resolutions": [[320, 180], [64, 32]],
      "base": {"atmosphere": {"lutResolution": "Small (8x32x16x8)"}},
      "views": [{"name": "high", "settings": {"camera": {"position": [0, 9000, 0]}}},
                {"name": "low", "settings": {"camera": {"position": [0, 50, 0]}, "sun": {"elevation": 5}}}],
      "variants": [{"name": "int", "settings": {"atmosphere": {"singleScattering": "Integration"}}},
                   {"name": "lut", "settings": {"atmosphere": {"singleScattering": "LUT", "integrationSteps": 7}}}],
      "ratios": [{"name": "lut / int", "numerator": "lut", "denominator": "int", "passes": ["Sky"], "paper": 0.89}]})json");
}

std::string refusal(json file) {
    try {
        parseBenchmarkPlan(file, State{}, "file.json");
    } catch (const SettingsError& e) {
        return e.what();
    }
    return "accepted";
}

TEST(BenchmarkPlan, ExpandsViewsVariantsAndResolutionsInOrder) {
    const BenchmarkPlan p = parseBenchmarkPlan(plan(), State{}, "file.json");
    EXPECT_EQ(p.warmupFrames, 2);
    EXPECT_EQ(p.measuredFrames, 4);
    EXPECT_TRUE(p.tables);
    ASSERT_EQ(p.scenarios.size(), 8u);
    EXPECT_EQ(p.scenarios[0].name, "high / int / 320x180");
    EXPECT_EQ(p.scenarios[3].name, "low / lut / 320x180");
    EXPECT_EQ(p.scenarios[7].name, "low / lut / 64x32");
    EXPECT_EQ(p.scenarios[7].resolution, glm::ivec2(64, 32));
    // Base, then view, then variant, over the defaults.
    const State& s = p.scenarios[3].state;
    EXPECT_EQ(s.atmosphere.resolution, LutResolution::Small);
    EXPECT_FLOAT_EQ(s.camera.position.y, 50.0f);
    EXPECT_FLOAT_EQ(s.sun.elevationDegrees, 5.0f);
    EXPECT_EQ(s.atmosphere.singleScattering, SingleScatteringMode::Table);
    EXPECT_EQ(s.atmosphere.integrationSteps, 7);
    EXPECT_EQ(p.scenarios[0].state.atmosphere.singleScattering, SingleScatteringMode::Integration);
    EXPECT_EQ(p.scenarios[0].state.atmosphere.integrationSteps, State{}.atmosphere.integrationSteps);
    EXPECT_EQ(p.baseState.atmosphere.resolution, LutResolution::Small);
    ASSERT_EQ(p.ratios.size(), 1u);
    EXPECT_EQ(p.ratios[0].paper, 0.89);
}

TEST(BenchmarkPlan, RefusesMalformedFilesNamingTheField) {
    json f = plan();
    f["resolutions"] = json::array({json::array({8, 8})});
    EXPECT_NE(refusal(f).find("resolutions"), std::string::npos) << refusal(f);
    f = plan();
    f["measuredFrames"] = 0;
    EXPECT_NE(refusal(f).find("measuredFrames"), std::string::npos);
    f = plan();
    f["variants"][1]["name"] = "int";
    EXPECT_NE(refusal(f).find("used twice"), std::string::npos);
    f = plan();
    f["ratios"][0]["numerator"] = "nothing";
    EXPECT_NE(refusal(f).find("'nothing' is not one of the variants"), std::string::npos);
    f = plan();
    f["views"][0]["settings"]["camera"]["fieldOfView"] = 500;
    EXPECT_NE(refusal(f).find("view 'high': camera.fieldOfView"), std::string::npos) << refusal(f);
    f = plan();
    f["variants"][0]["settings"]["atmosphere"]["singleScattering"] = "Fast";
    EXPECT_NE(refusal(f).find("variant 'int'"), std::string::npos) << refusal(f);
    f = plan();
    f["warmup"] = 3;
    EXPECT_NE(refusal(f).find("warmup: is not a field"), std::string::npos) << refusal(f);
    f = plan();
    f.erase("views");
    EXPECT_NE(refusal(f).find("views: is missing"), std::string::npos) << refusal(f);
    EXPECT_NE(refusal(f).find("file.json"), std::string::npos);
}

// Found by fuzzing the state file: the same JSON reading refuses a number too large for a double.
TEST(BenchmarkPlan, ANumberTooLargeForADoubleIsAnError) {
    const auto path = std::filesystem::temp_directory_path() / "firmament-huge-number-plan.json";
    std::ofstream(path) << R"({"frames": 8e619})";
    try {
        loadBenchmarkPlan(path, State{});
        ADD_FAILURE() << "no error";
    } catch (const SettingsError& e) {
        EXPECT_NE(std::string(e.what()).find("not valid JSON"), std::string::npos) << e.what();
    }
    std::filesystem::remove(path);
}

TEST(BenchmarkReport, MedianMinimumAndMaximum) {
    const TimeStatistics odd = timeStatistics({5.0, 1.0, 3.0});
    EXPECT_DOUBLE_EQ(odd.medianMs, 3.0);
    EXPECT_DOUBLE_EQ(odd.minMs, 1.0);
    EXPECT_DOUBLE_EQ(odd.maxMs, 5.0);
    EXPECT_DOUBLE_EQ(timeStatistics({4.0, 1.0, 2.0, 10.0}).medianMs, 3.0);
    EXPECT_DOUBLE_EQ(timeStatistics({}).medianMs, 0.0);
}

TEST(BenchmarkReport, RatiosDivideTheNumeratorsMediansByTheDenominators) {
    const BenchmarkPlan p = parseBenchmarkPlan(plan(), State{}, "file.json");
    std::vector<ScenarioResult> results;
    for (const BenchmarkScenario& s : p.scenarios) {
        ScenarioResult r;
        r.scenario = &s;
        const double scale = s.variant == "lut" ? 0.5 : 1.0;
        r.frameGpu = {10.0 * scale, 0.0, 0.0};
        r.passes = {{"Sky", {4.0 * scale * (s.view == "low" ? 2.0 : 1.0), 0.0, 0.0}}, {"Tone mapping", {1.0, 0.0, 0.0}}};
        results.push_back(r);
    }
    const std::vector<RatioResult> ratios = benchmarkRatios(p, results);
    ASSERT_EQ(ratios.size(), 4u);  // two views at two resolutions
    for (const RatioResult& r : ratios) {
        EXPECT_DOUBLE_EQ(r.frame, 0.5);
        EXPECT_DOUBLE_EQ(r.passes, 0.5);
    }
    const json report = benchmarkReport(p, results, {{"Yusov 2013", "abc", 2.0, 0.25}}, {"1.0", "adapter", "dxvk", "file.json"});
    EXPECT_EQ(report["scenarios"].size(), 8u);
    EXPECT_EQ(report["ratios"][0]["paper"], 0.89);
    EXPECT_EQ(report["tables"][0]["computeSeconds"], 2.0);
    EXPECT_EQ(report["firmament"]["implementation"], "dxvk");
    EXPECT_EQ(report["firmament"]["adapter"], "adapter");
    const std::string table = benchmarkTable(p, results, {{"Yusov 2013", "abc", 2.0, 0.25}});
    EXPECT_NE(table.find("lut / int, high, 320x180: frame 0.500, passes 0.500 (paper, on its own device: 0.89)"), std::string::npos) << table;
    EXPECT_NE(table.find("Yusov 2013: computed in 2.00 s, loaded in 0.250 s"), std::string::npos) << table;
}

// media/benchmarks/ (copied beside the executable): a variant or view with a setting the program
// no longer has would otherwise be found only when someone runs that benchmark.
TEST(BenchmarkPlan, EveryShippedScenarioFileLoads) {
    const std::filesystem::path folder = test::executableFolder() / "media" / "benchmarks";
    int files = 0;
    for (const auto& entry : std::filesystem::directory_iterator(folder)) {
        if (entry.path().extension() != ".json") continue;
        ++files;
        try {
            const BenchmarkPlan plan = loadBenchmarkPlan(entry.path(), State{});
            EXPECT_FALSE(plan.scenarios.empty()) << entry.path().string();
        } catch (const SettingsError& e) {
            ADD_FAILURE() << e.what();
        }
    }
    EXPECT_GE(files, 4) << "the scenario files in " << folder.string();
}

}  // namespace
}  // namespace firmament
