// The light shafts from outside, in the captured EXR (radiance before tone mapping):
//  - with no shadow caster (terrain off) nothing is occluded, so the brute-force pass must
//    draw what the atmosphere's own Sky and Aerial perspective passes draw, in every render
//    mode: the pass's plumbing (unmarched stretches, eq. 8, the sun's disc) adds nothing;
//  - over the mountains at sunrise the shafts take light out of the haze in the peaks'
//    shadows, and never add any;
//  - "Lighting only" removes the scene and keeps the scattered light;
//  - without shafts, single scattering None with higher orders Occluded draws the same light as
//    with them Unoccluded (the whole ray is lit), not single scattering (docs/atmosphere.md);
//  - epipolar sampling at its defaults draws, tone mapped, what the brute-force reference draws
//    (PSNR >= 46 dB, no 8-bit step more than 80 apart) over nine views: the sun ahead high and low, behind, at the side, below the
//    horizon, from 40 km, the open sky over the Earth's horizon without terrain, and below broken
//    clouds at sunset in both modes of Shafts from clouds;
//  - the clouds take light out of the haze below them, in both modes;
//  - every control of the epipolar sampling changes the image.
#include "core/ExrImage.h"
#include "core/PngImage.h"
#include "support/CaptureRadiance.h"
#include "support/ImageComparison.h"
#include "support/Process.h"
#include "support/TestPaths.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <string>
#include <vector>

namespace firmament::test {
namespace {

constexpr int kWidth = 96, kHeight = 54;

std::filesystem::path captureFolder() { return std::filesystem::temp_directory_path() / "firmament-light-shafts"; }

// Captures one frame at width x height; returns the EXR's RGB (radiance).
// The shafts alone: no clouds over them.
std::vector<float> capture(const std::string& name, std::vector<std::wstring> settings, int width = kWidth, int height = kHeight) {
    settings.insert(settings.begin(), L"clouds.enabled=off");
    return captureRadiance(captureFolder(), name, settings, width, height);
}

// The largest difference between two frames, relative to the brighter value (above a floor).
double largestRelativeDifference(const std::vector<float>& a, const std::vector<float>& b) {
    double worst = 0.0;
    for (size_t i = 0; i < a.size(); ++i)
        worst = std::max(worst, std::abs(static_cast<double>(a[i]) - b[i]) / std::max({static_cast<double>(a[i]), static_cast<double>(b[i]), 1e-3}));
    return worst;
}

// The orientation grid's ground (the Earth's sphere, with depth) and the sky, no terrain: no
// shadow caster, so the cascades are off.
const std::vector<std::wstring> kNoCasters{L"terrain.enabled=off", L"camera.position=0,1500,0", L"camera.pitch=-5", L"sun.elevation=12",
                                           L"sun.azimuth=10"};

const wchar_t* const kBruteForce = L"lightShafts.technique=Brute-force ray marching";

// Below a layer of broken clouds at sunset, looking toward the sun (the clouds at 2650-3350 m).
const std::vector<std::wstring> kUnderClouds{L"camera.position=0,1800,0", L"camera.yaw=100", L"camera.pitch=4", L"sun.elevation=6",
                                             L"sun.azimuth=100", L"clouds.cloudiness=0.5"};

// `view` with the clouds on and `mode` for their shafts.
std::vector<std::wstring> withClouds(std::vector<std::wstring> view, const wchar_t* mode) {
    view.insert(view.end(), {L"clouds.enabled=on", mode});
    return view;
}

// Shafts from clouds (Yusov 2014): below the layer, the clouds take light out of the haze, in
// both modes, and never add any; the two modes differ (the shadow map's clouds are opaque where
// they let through less than half of the light). The scattered light alone, brute force, the
// clouds drawn alike over all three.
TEST(LightShaftCapture, ShaftsFromCloudsTakeLightOutOfTheHazeBelowThem) {
    std::vector<std::wstring> base = kUnderClouds;
    base.insert(base.end(), {L"lightShafts.enabled=on", L"lightShafts.lightingOnly=on", kBruteForce});
    const std::vector<float> none = capture("clouds-none", withClouds(base, L"clouds.shaftsFromClouds=None"));
    const std::vector<float> transparency = capture("clouds-transparency", withClouds(base, L"clouds.shaftsFromClouds=Transparency map"));
    const std::vector<float> shadowMap = capture("clouds-shadow-map", withClouds(base, L"clouds.shaftsFromClouds=Shadow map"));
    ASSERT_FALSE(none.empty());
    ASSERT_EQ(transparency.size(), none.size());
    ASSERT_EQ(shadowMap.size(), none.size());
    const size_t pixels = none.size() / 3;
    int darker[2] = {}, different = 0;
    const std::vector<float>* modes[2] = {&transparency, &shadowMap};
    for (size_t i = 0; i < none.size(); ++i) {
        for (int m = 0; m < 2; ++m) {
            const float shadowed = (*modes[m])[i];
            ASSERT_TRUE(std::isfinite(shadowed)) << "component " << i;
            EXPECT_LE(shadowed, none[i] * 1.001f + 1e-6f) << "component " << i << " of mode " << m << ": a cloud's shadow adds light";
            if (i % 3 == 1 && shadowed < 0.8f * none[i]) ++darker[m];
        }
        if (i % 3 == 1 && std::abs(transparency[i] - shadowMap[i]) > 0.02f * none[i]) ++different;
    }
    std::printf("of %zu pixels, %d (transparency map) and %d (shadow map) lose more than 20%% of their scattered light to the clouds; the modes "
                "differ by more than 2%% at %d\n", pixels, darker[0], darker[1], different);
    EXPECT_GT(darker[0], static_cast<int>(pixels / 10));
    EXPECT_GT(darker[1], static_cast<int>(pixels / 10));
    EXPECT_GT(different, static_cast<int>(pixels / 20));
}

TEST(LightShaftCapture, WithoutCastersTheBruteForcePassDrawsTheAtmosphere) {
    const std::pair<const wchar_t*, const wchar_t*> modes[] = {
        {L"LUT", L"Unoccluded"}, {L"LUT", L"Occluded"}, {L"Integration", L"None"}, {L"Integration", L"Occluded"}, {L"None", L"Unoccluded"}};
    for (const auto& [single, multiple] : modes) {
        std::vector<std::wstring> settings = kNoCasters;
        settings.push_back(std::wstring(L"atmosphere.singleScattering=") + single);
        settings.push_back(std::wstring(L"atmosphere.multipleScattering=") + multiple);
        settings.push_back(L"lightShafts.enabled=off");
        const std::vector<float> plain = capture("plain", settings);
        settings.pop_back();
        settings.insert(settings.end(), {L"lightShafts.enabled=on", kBruteForce});
        const std::vector<float> shafts = capture("shafts", settings);
        ASSERT_EQ(plain.size(), shafts.size());
        const double difference = largestRelativeDifference(plain, shafts);
        std::printf("SS %ls + MS %ls: largest relative difference %.2e\n", single, multiple, difference);
        EXPECT_LT(difference, 1e-3) << "SS " << std::string(single, single + std::wcslen(single)) << " + MS "
                                    << std::string(multiple, multiple + std::wcslen(multiple));
    }
}

// A low sun over the range north-west of the start, looking towards it: the peaks' shadows
// cross the haze.
const std::vector<std::wstring> kLowSun{L"camera.position=0,3200,0", L"camera.yaw=-60", L"camera.pitch=-4", L"sun.elevation=5",
                                        L"sun.azimuth=-60"};

TEST(LightShaftCapture, ShaftsTakeLightOutOfTheHazeInTheMountainsShadows) {
    // The scattered light alone, marched from the first cascade on, and with nothing marched
    // (the first cascade to march beyond the four there are): the second is unshadowed.
    std::vector<std::wstring> settings = kLowSun;
    settings.insert(settings.end(), {L"lightShafts.enabled=on", L"lightShafts.lightingOnly=on", kBruteForce});
    const std::vector<float> shadowed = capture("shadowed-light", settings);
    settings.push_back(L"lightShafts.firstCascade=7");
    const std::vector<float> unshadowed = capture("unshadowed-light", settings);
    ASSERT_EQ(unshadowed.size(), shadowed.size());
    ASSERT_FALSE(shadowed.empty());
    int darker = 0;
    const size_t pixels = shadowed.size() / 3;
    for (size_t i = 0; i < shadowed.size(); ++i) {
        EXPECT_LE(shadowed[i], unshadowed[i] * 1.001f + 1e-6f) << "component " << i << ": a shadow adds light";
        if (i % 3 == 1 && shadowed[i] < 0.8f * unshadowed[i]) ++darker;
    }
    std::printf("%d of %zu pixels lose more than 20%% of their scattered light to the shadows\n", darker, pixels);
    EXPECT_GT(darker, static_cast<int>(pixels / 20)) << "the mountains' shadows should cross the haze";
}

TEST(LightShaftCapture, LightingOnlyShowsTheScatteredLightAlone) {
    std::vector<std::wstring> settings = kLowSun;
    settings.push_back(L"lightShafts.enabled=on");  // epipolar sampling
    const std::vector<float> full = capture("full", settings);
    settings.push_back(L"lightShafts.lightingOnly=on");
    const std::vector<float> light = capture("light-only", settings);
    ASSERT_EQ(full.size(), light.size());
    ASSERT_FALSE(full.empty());
    int dimmer = 0;
    for (size_t i = 0; i < full.size(); ++i) {
        EXPECT_LE(light[i], full[i] * 1.001f + 1e-6f) << "component " << i << ": lighting only adds light";
        dimmer += light[i] < 0.99f * full[i];
    }
    EXPECT_GT(dimmer, static_cast<int>(full.size() / 4)) << "the terrain's own radiance should be gone";
}

TEST(LightShaftCapture, SingleScatteringNoneShowsNoSingleScattering) {
    std::vector<std::wstring> settings = kNoCasters;
    settings.push_back(L"lightShafts.enabled=off");  // the atmosphere's own passes
    settings.push_back(L"atmosphere.singleScattering=None");
    settings.push_back(L"atmosphere.multipleScattering=Occluded");
    const std::vector<float> occluded = capture("none-occluded", settings);
    settings.back() = L"atmosphere.multipleScattering=Unoccluded";
    const std::vector<float> unoccluded = capture("none-unoccluded", settings);
    ASSERT_EQ(occluded.size(), unoccluded.size());
    ASSERT_FALSE(occluded.empty());
    EXPECT_LT(largestRelativeDifference(occluded, unoccluded), 1e-3) << "without shafts the whole ray is lit: the same high orders";
}

// Epipolar sampling against the brute-force reference, tone mapped (the PNG), at 480 x 270, by
// PSNR and by the largest difference of any pixel: the default 512 slices and 256 samples per
// slice are then sparser than the pixels along the border and the diagonal, so the test
// measures the sampling, not a supersampling.
TEST(LightShaftCapture, EpipolarSamplingMatchesTheBruteForceReference) {
    struct View {
        const char* label;
        std::vector<std::wstring> settings;
    };
    const std::vector<View> views{
        {"sun ahead, near the horizon", kLowSun},
        {"sun ahead, high", {L"camera.position=0,3200,0", L"camera.yaw=100", L"camera.pitch=10", L"sun.elevation=25", L"sun.azimuth=100"}},
        {"sun behind", {L"camera.position=0,3200,0", L"camera.yaw=-80", L"camera.pitch=-4", L"sun.elevation=5", L"sun.azimuth=100"}},
        {"sun at the side", {L"camera.position=0,3200,0", L"camera.yaw=10", L"camera.pitch=-4", L"sun.elevation=5", L"sun.azimuth=100"}},
        {"sun below the horizon", {L"camera.position=0,3200,0", L"camera.yaw=100", L"camera.pitch=-2", L"sun.elevation=-3", L"sun.azimuth=100"}},
        {"camera at 40 km", {L"camera.position=0,40000,0", L"camera.yaw=100", L"camera.pitch=-30", L"sun.elevation=5", L"sun.azimuth=100"}},
        // No terrain: the Earth's horizon is the only break, and nothing depth-tests it.
        {"open sky over the Earth's horizon", {L"terrain.enabled=off", L"scene.orientationGrid=off", L"camera.position=0,2,0", L"camera.pitch=20",
                                                 L"camera.fieldOfView=75", L"sun.elevation=45", L"sun.azimuth=40"}},
        // Shafts from clouds: the march reads the clouds' transparency map at every step, or the
        // clouds are casters in the cascades.
        {"sunset under broken clouds, transparency map", withClouds(kUnderClouds, L"clouds.shaftsFromClouds=Transparency map")},
        {"sunset under broken clouds, shadow map", withClouds(kUnderClouds, L"clouds.shaftsFromClouds=Shadow map")},
    };
    constexpr int width = 480, height = 270;
    for (const View& view : views) {
        std::vector<std::wstring> settings = view.settings;
        settings.push_back(L"lightShafts.enabled=on");
        capture("epipolar", settings, width, height);
        const Rgba8Image epipolar = readPng(captureFolder() / "epipolar.png");
        settings.push_back(kBruteForce);
        capture("brute-force", settings, width, height);
        const Rgba8Image reference = readPng(captureFolder() / "brute-force.png");
        const golden::Comparison c = golden::compare(epipolar, reference);
        std::printf("%s: PSNR %.1f dB, largest difference %d\n", view.label, c.psnrDb, c.maxDifference);
        // Measured: 49.2 dB (from 40 km) to 62.1 dB, the clouds' views 53.9 and 54.0; 3 dB spare.
        EXPECT_GE(c.psnrDb, 46.0) << view.label;
        // PSNR averages a few wrong pixels away: a sample whose depth disagrees with its own ray
        // lights a silhouette's pixels from the wrong side, by half the range or more. Measured:
        // 29 steps at most over the terrain, 74 under the clouds.
        EXPECT_LE(c.maxDifference, 80) << view.label;
    }
}

// Each control of the epipolar sampling, moved from its default, changes the radiance the frame
// holds (the EXR) somewhere: a control that does nothing is a bug. The depth-break controls act
// only where the bilateral weights fail; at this resolution the default sampling leaves no such
// pixel, so they are moved from a sparse sampling (32 slices of 32 samples), which does.
TEST(LightShaftCapture, EveryEpipolarControlChangesTheImage) {
    constexpr int width = 192, height = 108;
    std::vector<std::wstring> base = kLowSun;
    base.push_back(L"lightShafts.enabled=on");
    const std::vector<float> reference = capture("defaults", base, width, height);
    ASSERT_FALSE(reference.empty());
    std::vector<std::wstring> sparse = base;
    sparse.insert(sparse.end(), {L"lightShafts.slices=32", L"lightShafts.samplesPerSlice=32"});
    const std::vector<float> sparseReference = capture("sparse", sparse, width, height);
    ASSERT_EQ(sparseReference.size(), reference.size());
    const wchar_t* const breakControls[] = {L"lightShafts.correctDepthBreaks=on", L"lightShafts.showDepthBreaks=on"};
    // The epipole's density moves only what lies near the sun on the screen, and only where
    // something there is shadowed: unshadowed samples get the same light marched or not (pass 10
    // interpolates the share of the unshadowed light). So the sun sets behind the mountains.
    std::vector<std::wstring> sunset = base;
    sunset.push_back(L"sun.elevation=0.5");
    const std::vector<float> sunsetReference = capture("sunset", sunset, width, height);
    const wchar_t* const controls[] = {
        L"lightShafts.slices=128",
        L"lightShafts.samplesPerSlice=64",
        L"lightShafts.initialStep=4",
        L"lightShafts.refinementThreshold=0.3",
        L"lightShafts.showSampling=on",
        L"lightShafts.optimizeSampleLocations=off",
        L"lightShafts.refinementCriterion=Depth",
        L"lightShafts.extinction=Per pixel",
        L"lightShafts.scatteringScale=0.5",
        kBruteForce,
    };
    const auto check = [&](const wchar_t* control, const std::vector<std::wstring>& from, const std::vector<float>& unmoved) {
        std::vector<std::wstring> settings = from;
        settings.push_back(control);
        const std::vector<float> moved = capture("moved", settings, width, height);
        ASSERT_EQ(moved.size(), unmoved.size());
        int changed = 0;
        for (size_t i = 0; i < moved.size(); ++i)
            changed += std::abs(moved[i] - unmoved[i]) > 1e-3f * std::max({std::abs(moved[i]), std::abs(unmoved[i]), 1e-3f});
        std::printf("%ls: %d of %zu components changed\n", control, changed, moved.size());
        EXPECT_GT(changed, 0) << std::string(control, control + std::wcslen(control)) << " changes nothing";
    };
    for (const wchar_t* control : controls) check(control, base, reference);
    for (const wchar_t* control : breakControls) check(control, sparse, sparseReference);
    check(L"lightShafts.epipoleDensity=8", sunset, sunsetReference);
}

}  // namespace
}  // namespace firmament::test
