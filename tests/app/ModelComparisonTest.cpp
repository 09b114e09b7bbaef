// The atmosphere models side by side, from outside: a split frame is the model's frame on its
// left half and the compared model's on its right, pixel for pixel; a difference frame is the
// absolute difference of the two; the three-way frame is Yusov's, Bruneton's and Hillaire's in
// thirds. All compared in the captured EXR, before tone mapping.
#include "core/ExrImage.h"
#include "support/CaptureRadiance.h"
#include "support/HeadlessCapture.h"
#include "support/TestPaths.h"

#include <gtest/gtest.h>

#include <cmath>
#include <string>

namespace firmament::test {
namespace {

constexpr int kWidth = 64, kHeight = 40;

// A small headless capture over the orientation grid at sunset, with `extra` --set assignments. The
// terrain is off unless `extra` turns it on; the light shafts are off, so that Yusov's frame is
// drawn by the atmosphere's passes, as the comparison views draw it.
ExrFile capture(const std::filesystem::path& folder, const std::string& name, std::vector<std::wstring> extra) {
    HeadlessCapture c{{}, {L"camera.pitch=2", L"sun.elevation=8", L"atmosphere.lutResolution=small (8x32x16x8)", L"terrain.enabled=off",
                           L"lightShafts.enabled=off", L"clouds.enabled=off"},
                      kWidth, kHeight, 1, folder / (name + ".png")};
    c.settings.insert(c.settings.end(), extra.begin(), extra.end());
    const ProcessResult run = captureHeadless(c);
    EXPECT_EQ(run.exitCode, 0u) << run.output;
    return readExr(folder / (name + ".exr"));
}

TEST(ModelComparison, SplitAndDifferenceViewsAreMadeOfBothModels) {
    const auto folder = std::filesystem::temp_directory_path() / "firmament-model-comparison";
    std::filesystem::remove_all(folder);
    const ExrFile yusov = capture(folder, "yusov", {L"atmosphere.model=Yusov 2013"});
    const ExrFile bruneton = capture(folder, "bruneton", {L"atmosphere.model=Bruneton 2008"});
    const ExrFile split = capture(folder, "split", {L"atmosphere.comparison=split"});
    const ExrFile difference = capture(folder, "difference", {L"atmosphere.comparison=difference"});
    ASSERT_EQ(std::get<std::string>(split.attributes.at("firmament.atmosphere.comparison")), "Split");
    ASSERT_EQ(std::get<std::string>(bruneton.attributes.at("firmament.atmosphere.model")), "Bruneton 2008");

    int differing = 0;
    for (int y = 0; y < kHeight; ++y)
        for (int x = 0; x < kWidth; ++x)
            for (int c = 0; c < 3; ++c) {
                const float left = exrChannel(yusov, x, y, c), right = exrChannel(bruneton, x, y, c);
                ASSERT_EQ(exrChannel(split, x, y, c), x < kWidth / 2 ? left : right) << "split pixel " << x << "," << y;
                const float expected = std::abs(left - right);
                ASSERT_NEAR(exrChannel(difference, x, y, c), expected, 2e-3f * std::max(left, right) + 1e-6f) << "difference pixel " << x << "," << y;
                if (expected > 1e-3f * std::max(left, right)) ++differing;
            }
    // The models differ somewhere (the ground, which only Bruneton's model lights itself): the
    // difference view is not black.
    EXPECT_GT(differing, kWidth * kHeight / 10);
    std::filesystem::remove_all(folder);
}

// Over the terrain, the split view lights each side with its own model's tables as well: its
// left half is exactly Yusov's frame, its right half Bruneton's, terrain and shadows included.
TEST(ModelComparison, SplitViewLightsTheTerrainByEachModel) {
    const auto folder = std::filesystem::temp_directory_path() / "firmament-model-comparison-terrain";
    std::filesystem::remove_all(folder);
    const std::vector<std::wstring> terrain{L"terrain.enabled=on", L"camera.position=0,3000,0", L"camera.pitch=-20", L"camera.yaw=40"};
    const auto with = [&](const wchar_t* setting) {
        std::vector<std::wstring> settings = terrain;
        settings.push_back(setting);
        return settings;
    };
    const ExrFile yusov = capture(folder, "yusov", with(L"atmosphere.model=Yusov 2013"));
    const ExrFile bruneton = capture(folder, "bruneton", with(L"atmosphere.model=Bruneton 2008"));
    const ExrFile split = capture(folder, "split", with(L"atmosphere.comparison=split"));
    int terrainDiffers = 0;
    for (int y = kHeight / 2; y < kHeight; ++y)  // the lower half: terrain
        for (int x = 0; x < kWidth; ++x)
            for (int c = 0; c < 3; ++c) {
                const float left = exrChannel(yusov, x, y, c), right = exrChannel(bruneton, x, y, c);
                ASSERT_EQ(exrChannel(split, x, y, c), x < kWidth / 2 ? left : right) << "split pixel " << x << "," << y;
                if (std::abs(left - right) > 1e-3f * std::max(left, right)) ++terrainDiffers;
            }
    EXPECT_GT(terrainDiffers, kWidth * kHeight / 10);  // the two models do light it differently
    std::filesystem::remove_all(folder);
}

// Any two models compare: Hillaire 2020's on the left of Bruneton 2008's, and the difference of
// Yusov 2013's and Hillaire 2020's, over the terrain (each side lit by its own model).
TEST(ModelComparison, AnyTwoModelsCompare) {
    const auto folder = std::filesystem::temp_directory_path() / "firmament-model-comparison-pairs";
    std::filesystem::remove_all(folder);
    const std::vector<std::wstring> terrain{L"terrain.enabled=on", L"camera.position=0,3000,0", L"camera.pitch=-10", L"camera.yaw=40"};
    const auto with = [&](std::vector<std::wstring> extra) {
        extra.insert(extra.begin(), terrain.begin(), terrain.end());
        return extra;
    };
    const ExrFile yusov = capture(folder, "yusov", with({L"atmosphere.model=Yusov 2013"}));
    const ExrFile bruneton = capture(folder, "bruneton", with({L"atmosphere.model=Bruneton 2008"}));
    const ExrFile hillaire = capture(folder, "hillaire", with({L"atmosphere.model=Hillaire 2020"}));
    const ExrFile split =
        capture(folder, "split", with({L"atmosphere.model=Hillaire 2020", L"atmosphere.comparison=split", L"atmosphere.comparedModel=Bruneton 2008"}));
    const ExrFile difference =
        capture(folder, "difference", with({L"atmosphere.model=Yusov 2013", L"atmosphere.comparison=difference", L"atmosphere.comparedModel=Hillaire 2020"}));
    EXPECT_EQ(std::get<std::string>(split.attributes.at("firmament.atmosphere.comparedModel")), "Bruneton 2008");
    int differing = 0;
    for (int y = 0; y < kHeight; ++y)
        for (int x = 0; x < kWidth; ++x)
            for (int c = 0; c < 3; ++c) {
                ASSERT_EQ(exrChannel(split, x, y, c), x < kWidth / 2 ? exrChannel(hillaire, x, y, c) : exrChannel(bruneton, x, y, c))
                    << "split pixel " << x << "," << y;
                // The difference's ground is lit by the first model (Yusov's) in both terms.
                if (y < kHeight / 3) {
                    const float first = exrChannel(yusov, x, y, c), second = exrChannel(hillaire, x, y, c);
                    const float expected = std::abs(first - second);
                    ASSERT_NEAR(exrChannel(difference, x, y, c), expected, 2e-3f * std::max(first, second) + 1e-6f) << "difference pixel " << x << "," << y;
                    if (expected > 1e-3f * std::max(first, second)) ++differing;
                }
            }
    EXPECT_GT(differing, kWidth * kHeight / 30);
    std::filesystem::remove_all(folder);
}

// The three-way view: each model in its third exactly as it draws alone, the terrain lit by each.
TEST(ModelComparison, ThreeWayViewDrawsEachModelInItsThird) {
    const auto folder = std::filesystem::temp_directory_path() / "firmament-model-comparison-three";
    std::filesystem::remove_all(folder);
    const std::vector<std::wstring> terrain{L"terrain.enabled=on", L"camera.position=0,3000,0", L"camera.pitch=-10", L"camera.yaw=40"};
    const auto with = [&](const wchar_t* setting) {
        std::vector<std::wstring> settings = terrain;
        settings.push_back(setting);
        return settings;
    };
    const ExrFile models[] = {capture(folder, "yusov", with(L"atmosphere.model=Yusov 2013")),
                              capture(folder, "bruneton", with(L"atmosphere.model=Bruneton 2008")),
                              capture(folder, "hillaire", with(L"atmosphere.model=Hillaire 2020"))};
    const ExrFile three = capture(folder, "three", with(L"atmosphere.comparison=Three-way"));
    ASSERT_EQ(std::get<std::string>(three.attributes.at("firmament.atmosphere.comparison")), "Three-way");
    for (int y = 0; y < kHeight; ++y)
        for (int x = 0; x < kWidth; ++x) {
            const int third = x < kWidth / 3 ? 0 : x < 2 * kWidth / 3 ? 1 : 2;
            for (int c = 0; c < 3; ++c) ASSERT_EQ(exrChannel(three, x, y, c), exrChannel(models[third], x, y, c)) << "pixel " << x << "," << y;
        }
    std::filesystem::remove_all(folder);
}

}  // namespace
}  // namespace firmament::test
