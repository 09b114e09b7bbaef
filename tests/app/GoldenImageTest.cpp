// Golden images: the canonical views of tests/golden/views.json, each captured headless
// (HeadlessCapture.h: every view of the test process through one firmament.exe) and compared with the committed tests/golden/<name>.png. The tolerance is the
// file's (PSNR over RGB and the largest difference of any channel, in 8-bit steps). A failure
// writes the captured image and an amplified difference image into test-output/golden/ and
// names them. With FIRMAMENT_UPDATE_GOLDENS=1 the captures are written to
// test-output/golden/update/ instead of compared; tools/update-goldens copies them into
// tests/golden/ (docs/building.md, "Golden images").
// A view whose picture legitimately differs on one Direct3D 11 implementation names it, and why,
// in its "implementations" object; that implementation's image is tests/golden/<id>/<name>.png
// (docs/building.md, "Two Direct3D 11 implementations").
#include "core/PngImage.h"
#include "gpu/D3D11Implementation.h"
#include "support/ImageComparison.h"
#include "support/HeadlessCapture.h"
#include "support/TestPaths.h"

#include <gtest/gtest.h>
#include <nlohmann/json.hpp>

#include <algorithm>
#include <cctype>
#include <cstdlib>
#include <fstream>
#include <string>
#include <vector>

namespace firmament::test {
namespace {

std::filesystem::path goldenFolder() { return executableFolder() / "golden"; }
std::filesystem::path outputFolder() { return executableFolder().parent_path() / "test-output" / "golden"; }

nlohmann::json readViews() {
    std::ifstream in(goldenFolder() / "views.json");
    if (!in) return {};
    return nlohmann::json::parse(in, nullptr, /*allow_exceptions=*/false);
}

// The view names, read when the test cases are made (a missing or broken file gives none,
// and the ViewsFile test below fails).
std::vector<std::string> viewNames() {
    std::vector<std::string> names;
    const nlohmann::json views = readViews();
    if (!views.is_object() || !views.contains("views")) return names;
    for (const auto& view : views["views"]) names.push_back(view.value("name", std::string("unnamed")));
    return names;
}

// The golden image of `view` on the implementation the tests run on, relative to the golden
// folder: its own image where the view declares one.
std::filesystem::path goldenImage(const nlohmann::json& view) {
    const std::string name = view["name"].get<std::string>() + ".png", implementation = chosenD3D11Implementation();
    if (view.contains("implementations") && view["implementations"].contains(implementation)) return std::filesystem::path(implementation) / name;
    return name;
}

bool updating() {
    const char* value = std::getenv("FIRMAMENT_UPDATE_GOLDENS");
    return value && std::string(value) == "1";
}

TEST(GoldenImages, ViewsFileListsAtLeastEightNamedViews) {
    const nlohmann::json views = readViews();
    ASSERT_TRUE(views.is_object()) << "cannot read " << (goldenFolder() / "views.json").string();
    ASSERT_TRUE(views["resolution"].is_array() && views["resolution"].size() == 2);
    ASSERT_TRUE(views["frames"].is_number_integer());
    ASSERT_TRUE(views["tolerance"]["minPsnrDb"].is_number() && views["tolerance"]["maxDifference"].is_number_integer());
    ASSERT_GE(views["views"].size(), 8u);
    std::vector<std::string> seen;
    for (const auto& view : views["views"]) {
        ASSERT_TRUE(view["name"].is_string() && view["what"].is_string() && view["settings"].is_object()) << view.dump();
        const std::string name = view["name"];
        EXPECT_EQ(std::find(seen.begin(), seen.end(), name), seen.end()) << "two views are named " << name;
        seen.push_back(name);
        // Each implementation's own image is declared with its reason, and exists.
        if (!view.contains("implementations")) continue;
        ASSERT_TRUE(view["implementations"].is_object()) << name << ": \"implementations\" maps an implementation to why its image differs";
        for (const auto& [implementation, why] : view["implementations"].items()) {
            EXPECT_TRUE(why.is_string() && !why.get<std::string>().empty()) << name << ": say why " << implementation << " has an image of its own";
            EXPECT_TRUE(std::filesystem::exists(goldenFolder() / implementation / (name + ".png"))) << name << " declares an image for " << implementation;
        }
    }
    // And no image stands in an implementation's folder that no view declares.
    for (const D3D11Implementation id : {D3D11Implementation::Windows, D3D11Implementation::Wined3d, D3D11Implementation::Dxvk}) {
        const std::string implementation = implementationId(id);
        const std::filesystem::path folder = goldenFolder() / implementation;
        if (!std::filesystem::is_directory(folder)) continue;
        for (const auto& image : std::filesystem::directory_iterator(folder)) {
            const std::string name = image.path().stem().string();
            bool declared = false;
            for (const auto& view : views["views"])
                if (view["name"] == name && view.contains("implementations") && view["implementations"].contains(implementation)) declared = true;
            EXPECT_TRUE(declared) << image.path().string() << " is no view's image for " << implementation;
        }
    }
}

class GoldenImage : public ::testing::TestWithParam<std::string> {};

TEST_P(GoldenImage, MatchesTheCommittedImage) {
    const std::string name = GetParam();
    const nlohmann::json views = readViews();
    const nlohmann::json* view = nullptr;
    for (const auto& v : views["views"])
        if (v["name"] == name) view = &v;
    ASSERT_NE(view, nullptr);

    const auto scratch = std::filesystem::temp_directory_path() / ("firmament-golden-" + name);
    std::filesystem::remove_all(scratch);
    std::filesystem::create_directories(scratch);
    const ProcessResult run = captureHeadless({(*view)["settings"], {}, views["resolution"][0].get<int>(), views["resolution"][1].get<int>(),
                                               views["frames"].get<int>(), scratch / "capture.png"});
    ASSERT_EQ(run.exitCode, 0u) << run.output;
    const Rgba8Image captured = readPng(scratch / "capture.png");
    std::filesystem::remove_all(scratch);

    const std::filesystem::path image = goldenImage(*view);
    if (updating()) {
        std::filesystem::create_directories((outputFolder() / "update" / image).parent_path());
        writePng(outputFolder() / "update" / image, captured);
        std::printf("updated: %s\n", (outputFolder() / "update" / image).string().c_str());
        return;
    }
    const auto goldenPath = goldenFolder() / image;
    ASSERT_TRUE(std::filesystem::exists(goldenPath)) << "no golden image " << goldenPath.string()
                                                     << ": run tools/update-goldens and review the new image (docs/building.md, \"Golden images\")";
    const Rgba8Image golden = readPng(goldenPath);
    ASSERT_EQ(captured.width, golden.width);
    ASSERT_EQ(captured.height, golden.height);

    const nlohmann::json tolerance = view->contains("tolerance") ? (*view)["tolerance"] : views["tolerance"];
    const double minPsnr = tolerance["minPsnrDb"].get<double>();
    const int maxDifference = tolerance["maxDifference"].get<int>();
    const golden::Comparison c = golden::compare(captured, golden);
    std::printf("%s: PSNR %.2f dB (at least %.1f), largest difference %d (at most %d) at (%d, %d), %zu pixels differ\n", name.c_str(),
                c.psnrDb, minPsnr, c.maxDifference, maxDifference, c.worstPixel.x, c.worstPixel.y, c.differingPixels);
    if (c.psnrDb >= minPsnr && c.maxDifference <= maxDifference) return;

    std::filesystem::create_directories(outputFolder());
    const auto actualPath = outputFolder() / (name + ".actual.png"), diffPath = outputFolder() / (name + ".diff.png");
    writePng(actualPath, captured);
    writePng(diffPath, golden::differenceImage(captured, golden));
    ADD_FAILURE() << name << " (" << (*view)["what"].get<std::string>() << ") differs from its golden image " << goldenPath.string()
                  << ": PSNR " << c.psnrDb << " dB (at least " << minPsnr << "), largest difference " << c.maxDifference << " (at most "
                  << maxDifference << ").\n  captured:   " << actualPath.string() << "\n  difference: " << diffPath.string()
                  << " (x" << golden::kDifferenceGain << ")\nIf the change is intended, run tools/update-goldens and review the images.";
}

// Test names take letters, digits and underscores.
std::string testName(const ::testing::TestParamInfo<std::string>& view) {
    std::string name = view.param;
    for (char& ch : name)
        if (!std::isalnum(static_cast<unsigned char>(ch))) ch = '_';
    return name;
}

INSTANTIATE_TEST_SUITE_P(Views, GoldenImage, ::testing::ValuesIn(viewNames()), testName);
GTEST_ALLOW_UNINSTANTIATED_PARAMETERIZED_TEST(GoldenImage);

}  // namespace
}  // namespace firmament::test
