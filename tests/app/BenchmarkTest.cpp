// --benchmark end to end, on small tables and frames: the JSON is complete and well formed
// (every scenario with its resolution, settings and every pass's median, minimum and maximum;
// the ratios agree with the scenarios' own medians; the tables' computing and loading times;
// the adapter and the version), the table is printed, and a bad scenario file is refused. No
// time is asserted: these machines are shared (docs/performance.md).
#include "support/Process.h"
#include "support/TestPaths.h"

#include <gtest/gtest.h>
#include <nlohmann/json.hpp>

#include <fstream>
#include <set>
#include <string>

namespace firmament::test {
namespace {

using nlohmann::json;

const char* kScenarios = R"json({
  "format": 1, "name": "test", "warmupFrames": 1, "measuredFrames": 3, "tables": true,
  "resolutions": [[96, 54]],
  "base": {"atmosphere": {"lutResolution": "Small (8x32x16x8)"}, "shadows": {"resolution": "512", "cascades": 2}, "lightShafts": {"enabled": false},
           "clouds": {"enabled": true, "rings": 2, "ringDimension": 32}},
  "views": [{"name": "valley", "settings": {"camera": {"position": [0, 3200, 0], "yaw": 40, "pitch": -8}}}],
  "variants": [{"name": "SS-Int", "settings": {"atmosphere": {"singleScattering": "Integration", "multipleScattering": "None"}}},
               {"name": "SS-LUT + MS-Occluded", "settings": {"atmosphere": {"singleScattering": "LUT", "multipleScattering": "Occluded"}}}],
  "ratios": [{"name": "LUT / Int", "numerator": "SS-LUT + MS-Occluded", "denominator": "SS-Int",
              "passes": ["Sky", "Aerial perspective"], "paper": 0.89}]})json";

void expectStatistics(const json& t, const std::string& where) {
    ASSERT_TRUE(t.is_object()) << where;
    for (const char* key : {"medianMs", "minMs", "maxMs"}) ASSERT_TRUE(t[key].is_number()) << where << "." << key;
    EXPECT_GE(t["minMs"].get<double>(), 0.0) << where;
    EXPECT_LE(t["minMs"].get<double>(), t["medianMs"].get<double>()) << where;
    EXPECT_LE(t["medianMs"].get<double>(), t["maxMs"].get<double>()) << where;
}

TEST(Benchmark, WritesCompleteWellFormedJsonAndPrintsTheTable) {
    const auto folder = std::filesystem::temp_directory_path() / "firmament-benchmark-test";
    std::filesystem::remove_all(folder);
    std::filesystem::create_directories(folder);
    std::ofstream(folder / "scenarios.json") << kScenarios;
    const auto output = folder / "results.json";
    const ProcessResult run = runProcess(firmamentExe(), {L"--benchmark", (folder / "scenarios.json").wstring(), L"--benchmark-output", output.wstring()});
    ASSERT_EQ(run.exitCode, 0u) << run.output;
    EXPECT_NE(run.output.find("valley / SS-Int / 96x54"), std::string::npos) << run.output;
    EXPECT_NE(run.output.find("LUT / Int, valley, 96x54: frame "), std::string::npos) << run.output;
    EXPECT_NE(run.output.find("Yusov 2013: computed in "), std::string::npos) << run.output;

    const json report = json::parse(std::ifstream(output));
    EXPECT_FALSE(report["firmament"]["version"].get<std::string>().empty());
    EXPECT_FALSE(report["firmament"]["adapter"].get<std::string>().empty());
    EXPECT_EQ(report["firmament"]["implementation"], chosenD3D11Implementation());
    EXPECT_EQ(report["benchmark"]["measuredFrames"], 3);
    EXPECT_EQ(report["benchmark"]["warmupFrames"], 1);
    ASSERT_EQ(report["scenarios"].size(), 2u);
    std::map<std::string, double> skyAndAerial, frames;
    for (const json& s : report["scenarios"]) {
        const std::string name = s["name"];
        EXPECT_EQ(s["resolution"], json::array({96, 54})) << name;
        expectStatistics(s["frame"]["gpu"], name + " frame.gpu");
        expectStatistics(s["frame"]["wall"], name + " frame.wall");
        EXPECT_GT(s["frame"]["wall"]["medianMs"].get<double>(), 0.0) << name;
        // The whole state, the variant's modes in it.
        EXPECT_EQ(s["settings"]["atmosphere"]["singleScattering"], s["variant"] == "SS-Int" ? "Integration" : "LUT") << name;
        EXPECT_EQ(s["settings"]["shadows"]["cascades"], 2) << name;
        std::set<std::string> passes;
        for (const json& p : s["passes"]) {
            expectStatistics(p["gpu"], name + " " + p["name"].get<std::string>());
            passes.insert(p["name"].get<std::string>());
            if (p["name"] == "Sky" || p["name"] == "Aerial perspective") skyAndAerial[s["variant"]] += p["gpu"]["medianMs"].get<double>();
        }
        for (const char* pass : {"Clear frame targets", "Shadow cascades", "Terrain", "Sky", "Aerial perspective", "Scene luminance",
                                 "Light adaptation", "Tone mapping", "Clouds: valid cells", "Clouds: particle generation", "Clouds: sort",
                                 "Clouds: shading", "Clouds: blending resolve", "Clouds: low-resolution depth", "Clouds: upsample",
                                 "Clouds: light-space tiling", "Clouds: particle opacity"})
            EXPECT_TRUE(passes.count(pass)) << name << " has no pass " << pass;
        EXPECT_FALSE(passes.count("Atmosphere tables (Yusov)")) << "the warm-up frames compute the tables, not the measured ones";
        frames[s["variant"]] = s["frame"]["gpu"]["medianMs"].get<double>();
        // The clouds' counts: particles generated from the valid cells, none over the capacity.
        EXPECT_GT(s["counts"]["cloud valid cells"].get<double>(), 0.0) << name;
        EXPECT_GE(s["counts"]["cloud particles"].get<double>(), s["counts"]["cloud valid cells"].get<double>()) << name;
        EXPECT_EQ(s["counts"]["cloud particles over capacity"].get<double>(), 0.0) << name;
        // Volume-aware blending by default: through the per-pixel lists under wined3d, their
        // fragments counted; DXVK has rasterizer-ordered views, whose path keeps no lists.
        // The path is counted, and its memory: the ordered path's two stores of 24 bytes a
        // low-resolution pixel (Downscale 2x of 96x54), or the lists' heads and pool.
        const bool ordered = chosenD3D11Implementation() == "dxvk";
        EXPECT_EQ(s["counts"]["cloud blending through rasterizer-ordered views"], ordered ? 1.0 : 0.0) << name;
        if (ordered) {
            EXPECT_FALSE(s["counts"].contains("cloud fragments")) << name;
            EXPECT_NEAR(s["counts"]["cloud blending memory (MiB)"].get<double>(), 48.0 * 27.0 * 24.0 / (1024.0 * 1024.0), 1e-9) << name;
        } else {
            EXPECT_GT(s["counts"]["cloud fragments"].get<double>(), 0.0) << name;
            EXPECT_GT(s["counts"]["cloud blending memory (MiB)"].get<double>(), 48.0 * 27.0 * 4.0 / (1024.0 * 1024.0)) << name;
        }
        // Light occlusion: the particles tiled from the sun.
        EXPECT_GE(s["counts"]["cloud light-space tile nodes"].get<double>(), s["counts"]["cloud particles"].get<double>()) << name;
    }
    ASSERT_EQ(report["ratios"].size(), 1u);
    const json& ratio = report["ratios"][0];
    EXPECT_EQ(ratio["paper"], 0.89);
    ASSERT_GT(frames["SS-Int"], 0.0);
    EXPECT_NEAR(ratio["frame"].get<double>(), frames["SS-LUT + MS-Occluded"] / frames["SS-Int"], 1e-9);
    ASSERT_GT(skyAndAerial["SS-Int"], 0.0);
    EXPECT_NEAR(ratio["passes"]["ratio"].get<double>(), skyAndAerial["SS-LUT + MS-Occluded"] / skyAndAerial["SS-Int"], 1e-9);
    ASSERT_EQ(report["tables"].size(), 2u);
    EXPECT_EQ(report["tables"][0]["tables"], "Yusov 2013");
    EXPECT_EQ(report["tables"][1]["tables"], "Cloud particle (optical depth)");
    for (const json& t : report["tables"]) {
        EXPECT_GT(t["computeSeconds"].get<double>(), 0.0);
        EXPECT_GT(t["cacheLoadSeconds"].get<double>(), 0.0);
    }
    EXPECT_NE(run.output.find("cloud particles"), std::string::npos) << run.output;
    std::filesystem::remove_all(folder);
}

TEST(Benchmark, RefusesABadScenarioFileAndConflictingOptions) {
    const auto folder = std::filesystem::temp_directory_path() / "firmament-benchmark-bad";
    std::filesystem::remove_all(folder);
    std::filesystem::create_directories(folder);
    json bad = json::parse(kScenarios);
    bad["variants"][0]["settings"]["atmosphere"]["integrationSteps"] = 1000;
    std::ofstream(folder / "bad.json") << bad.dump();
    ProcessResult run = runProcess(firmamentExe(), {L"--benchmark", (folder / "bad.json").wstring()});
    EXPECT_EQ(run.exitCode, 2u) << run.output;
    EXPECT_NE(run.output.find("variant 'SS-Int': atmosphere.integrationSteps: 1000 is outside 5 to 100"), std::string::npos) << run.output;
    run = runProcess(firmamentExe(), {L"--benchmark", (folder / "missing.json").wstring()});
    EXPECT_EQ(run.exitCode, 2u) << run.output;
    EXPECT_NE(run.output.find("missing.json"), std::string::npos) << run.output;
    run = runProcess(firmamentExe(), {L"--benchmark", (folder / "bad.json").wstring(), L"--frames", L"3"});
    EXPECT_EQ(run.exitCode, 2u) << run.output;
    std::filesystem::remove_all(folder);
}

}  // namespace
}  // namespace firmament::test
