// The clouds from outside, in captured EXRs (radiance before tone mapping): Show particles draws
// the field as geometry and as transparency, finite everywhere; the transparency view brightens
// the dark terrain under it with white cloud; and every cloud control changes the picture. The
// path-traced reference traced in strides draws, after a round, what a full pass draws; the light
// terms add up to the whole.
#include "clouds/VolumeBlendingPass.h"
#include "gpu/Device.h"
#include "support/CaptureRadiance.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdio>
#include <cwchar>
#include <initializer_list>
#include <string>
#include <vector>

namespace firmament::test {
namespace {

constexpr int kWidth = 96, kHeight = 54;

// One frame over the mountains from 8 km up, looking 30 degrees down, with `settings`; the
// EXR's RGB, or empty when the run failed.
std::vector<float> capture(const std::string& name, std::vector<std::wstring> settings) {
    settings.insert(settings.begin(), {L"camera.position=0,8000,0", L"camera.pitch=-30", L"sun.elevation=35"});
    return captureRadiance(std::filesystem::temp_directory_path() / "firmament-clouds", name, settings, kWidth, kHeight);
}

// `base` and `extra` settings.
std::vector<std::wstring> plus(std::vector<std::wstring> base, std::initializer_list<const wchar_t*> extra) {
    base.insert(base.end(), extra.begin(), extra.end());
    return base;
}

double mean(const std::vector<float>& v) {
    double sum = 0.0;
    for (float x : v) sum += x;
    return v.empty() ? 0.0 : sum / static_cast<double>(v.size());
}

bool allFinite(const std::vector<float>& v) {
    for (float x : v)
        if (!std::isfinite(x)) return false;
    return true;
}

// The share of the frame's values that differ by more than 1%.
double changedShare(const std::vector<float>& a, const std::vector<float>& b) {
    if (a.size() != b.size() || a.empty()) return 0.0;
    size_t changed = 0;
    for (size_t i = 0; i < a.size(); ++i) changed += std::abs(a[i] - b[i]) > 0.01f * std::max(std::abs(a[i]), std::abs(b[i])) + 1e-6f;
    return static_cast<double>(changed) / static_cast<double>(a.size());
}

TEST(CloudCapture, ShowParticlesDrawsTheFieldAsGeometryAndAsTransparency) {
    const std::vector<float> off = capture("off", {L"clouds.enabled=off"});
    const std::vector<float> shapes = capture("shapes", {L"clouds.showParticles=Bounding shapes"});
    const std::vector<float> transparency = capture("transparency", {L"clouds.showParticles=Optical depth"});
    ASSERT_FALSE(off.empty());
    for (const auto* frame : {&shapes, &transparency}) EXPECT_TRUE(allFinite(*frame));
    // Most of the frame is covered at the default cloudiness.
    EXPECT_GT(changedShare(off, shapes), 0.5);
    EXPECT_GT(changedShare(off, transparency), 0.5);
    EXPECT_GT(changedShare(shapes, transparency), 0.5);
    // White cloud over dark mountains: brighter on average.
    EXPECT_GT(mean(transparency), 1.5 * mean(off));
}

TEST(CloudCapture, EveryCloudControlChangesTheParticles) {
    const std::vector<std::wstring> base{L"clouds.showParticles=Optical depth"};
    const std::vector<float> defaults = capture("defaults", base);
    ASSERT_FALSE(defaults.empty());
    const wchar_t* const changes[] = {L"clouds.cloudiness=0.4",       L"clouds.altitude=5000",         L"clouds.thickness=1400",
                                      L"clouds.densityResolution=128", L"clouds.rings=3",               L"clouds.ringDimension=64",
                                      L"clouds.maxLayers=1",          L"clouds.particleDistance=50000", L"clouds.particleDensity=Thresholded noise",
                                      L"clouds.particleDensity=Pyroclastic"};
    int index = 0;
    for (const wchar_t* change : changes) {
        std::vector<std::wstring> settings = base;
        settings.push_back(change);
        const std::vector<float> changed = capture("control-" + std::to_string(index++), settings);
        EXPECT_TRUE(allFinite(changed));
        EXPECT_GT(changedShare(defaults, changed), 0.02) << std::string(change, change + std::wcslen(change));
    }
}

// The frame's mean red over blue, where the clouds are (the top third of the frame from below).
double redOverBlueAbove(const std::vector<float>& rgb) {
    double red = 0.0, blue = 0.0;
    for (int y = 0; y < kHeight / 3; ++y)
        for (int x = 0; x < kWidth; ++x) {
            red += rgb[(static_cast<size_t>(y) * kWidth + x) * 3];
            blue += rgb[(static_cast<size_t>(y) * kWidth + x) * 3 + 2];
        }
    return red / std::max(blue, 1e-9);
}

// Through each atmosphere model's tables: Yusov's in the quick tier, the other two in the full
// tier (ShadedCloudsThroughTheOtherModelsGlowRedAtSunset; the quick tier's goldens clouds-bruneton
// and clouds-hillaire draw the clouds through them).
void expectCloudsHideTheBlueSkyAndGlowRedAtSunset(std::initializer_list<const wchar_t*> models) {
    for (const wchar_t* model : models) {
        const std::string name(model + std::wcslen(L"atmosphere.model="), model + std::wcslen(model));
        const std::vector<std::wstring> below{model, L"camera.position=0,1500,0", L"camera.pitch=25", L"clouds.cloudiness=1"};
        const std::string tag = name.substr(0, 4);
        const std::vector<float> clearNoon = capture("clear-noon-" + tag, plus(below, {L"sun.elevation=50", L"clouds.enabled=off"}));
        const std::vector<float> cloudyNoon = capture("cloudy-noon-" + tag, plus(below, {L"sun.elevation=50", L"clouds.enabled=on"}));
        const std::vector<float> cloudySunset = capture("cloudy-sunset-" + tag, plus(below, {L"sun.elevation=3", L"clouds.enabled=on"}));
        ASSERT_FALSE(clearNoon.empty());
        EXPECT_TRUE(allFinite(cloudyNoon)) << name;
        EXPECT_TRUE(allFinite(cloudySunset)) << name;
        // Overcast: white-grey cloud instead of the blue sky overhead.
        const double clear = redOverBlueAbove(clearNoon), noon = redOverBlueAbove(cloudyNoon), sunset = redOverBlueAbove(cloudySunset);
        std::printf("%s: red / blue overhead: clear %.3f, clouds at noon %.3f, clouds at sunset %.3f\n", name.c_str(), clear, noon, sunset);
        EXPECT_GT(noon, clear * 1.3) << name;
        // The sun's light through the long path at sunset: the clouds redder than at noon. Measured
        // 1.42 and 1.18 times (Yusov's, Bruneton's). The bound was 1.3 until the multiple scattering
        // took the scaled transmittance (2026-12-05), which lets more of the sun's white light into
        // the noon bases (their red / blue rose from 0.50 to 0.72); the path-traced reference puts
        // sunset bases far redder still (docs/clouds.md, "Against the reference"), so this is a
        // floor, not the goal.
        EXPECT_GT(sunset, noon * 1.1) << name;
    }
}

TEST(CloudCapture, ShadedCloudsHideTheBlueSkyAndGlowRedAtSunset) { expectCloudsHideTheBlueSkyAndGlowRedAtSunset({L"atmosphere.model=Yusov 2013"}); }

TEST(CloudCapture, ShadedCloudsThroughTheOtherModelsGlowRedAtSunset) {
    expectCloudsHideTheBlueSkyAndGlowRedAtSunset({L"atmosphere.model=Bruneton 2008", L"atmosphere.model=Hillaire 2020"});
}

// Volume-aware blending (docs/clouds.md, "Blending") against plain alpha blending, from below
// broken clouds: the same where no particle is, different where particles are (where they
// intersect), similar on the whole. (Auto picks the device's path: the comparison of the two
// volume-aware paths is the next test's.)
TEST(CloudCapture, VolumeAwareBlendingChangesOnlyWhereParticlesAre) {
    // The clouds' shadows off: the clear frame is the one without clouds.
    const std::vector<std::wstring> below{L"camera.position=0,1500,0", L"camera.pitch=10", L"clouds.cloudiness=0.35", L"clouds.shadows=off"};
    const std::vector<float> clear = capture("blend-clear", plus(below, {L"clouds.enabled=off"}));
    const std::vector<float> alpha = capture("blend-alpha", plus(below, {L"clouds.volumetricBlending=off"}));
    const std::vector<float> volume = capture("blend-volume", plus(below, {L"clouds.volumetricBlending=on"}));
    ASSERT_FALSE(clear.empty());
    ASSERT_EQ(volume.size(), alpha.size());
    EXPECT_TRUE(allFinite(volume));
    size_t empty = 0, emptyChanged = 0;
    for (size_t i = 0; i < clear.size(); ++i) {
        if (std::abs(alpha[i] - clear[i]) > 1e-6f * std::abs(clear[i])) continue;  // a particle covers it
        ++empty;
        emptyChanged += std::abs(volume[i] - clear[i]) > 0.01f * std::abs(clear[i]) + 1e-6f;
    }
    const double differs = changedShare(alpha, volume);
    std::printf("values without particles: %zu, of them changed by volume-aware blending: %zu; values that differ from alpha blending: %.1f%%\n", empty,
                emptyChanged, 100.0 * differs);
    EXPECT_GT(empty, clear.size() / 10);
    EXPECT_LE(emptyChanged, empty / 200);  // (a particle too thin to change alpha blending by 1e-6 may show)
    EXPECT_GT(differs, 0.05);
    EXPECT_NEAR(mean(volume) / mean(alpha), 1.0, 0.25);
}

// The two volume-aware paths in a frame: the rasterizer-ordered one merges each pixel's fragments
// as they arrive, the lists sort them by their back first, so the two differ where three or more
// particles overlap (docs/clouds.md, "Blending"), but only there. Where the device has no
// rasterizer-ordered views, the program runs the lists for both requests, so the comparison
// would hold a path to itself: it is reported skipped with the reason.
TEST(CloudCapture, TheOrderedPathDrawsTheFrameTheListsDraw) {
    const Device warp(DeviceOptions{DriverType::Warp, std::nullopt, false});
    const BlendingSupport support = queryBlendingSupport(warp.device());
    if (!support.rasterizerOrderedViews || !support.typedUavLoads)
        GTEST_SKIP() << "not run: " << warp.adapterName() << " reports no rasterizer-ordered views (ROVsSupported "
                     << support.rasterizerOrderedViews << ", typed UAV loads " << support.typedUavLoads
                     << "): Blending path Rasterizer-ordered views runs the per-pixel lists here";
    const std::vector<std::wstring> below{L"camera.position=0,1500,0", L"camera.pitch=10", L"clouds.cloudiness=0.35"};
    const std::vector<float> lists = capture("path-lists", plus(below, {L"clouds.blendingPath=Per-pixel lists"}));
    const std::vector<float> ordered = capture("path-ordered", plus(below, {L"clouds.blendingPath=Rasterizer-ordered views"}));
    ASSERT_FALSE(lists.empty());
    ASSERT_EQ(ordered.size(), lists.size());
    EXPECT_TRUE(allFinite(ordered));
    // Bounds from the one device that has run it so far (DXVK on lavapipe, 1280 x 720: 52.6 dB
    // tone-mapped, 1% of the pixels more than 2 steps of 255 apart).
    const double differs = changedShare(lists, ordered);
    std::printf("values where the ordered path differs from the lists by more than 1%%: %.2f%%\n", 100.0 * differs);
    EXPECT_LT(differs, 0.05);
    EXPECT_NEAR(mean(ordered) / mean(lists), 1.0, 0.02);
}

// The visibility pass (docs/clouds.md, "Visibility") culls only particles that draw nothing: from
// below, from above, inside the layer and looking back along the wind, the frame with culling is
// the frame without it, value for value.
TEST(CloudCapture, TheVisibilityPassChangesNoPixel) {
    const std::vector<std::pair<std::string, std::vector<std::wstring>>> views{
        {"below", {L"camera.position=0,1500,0", L"camera.yaw=30", L"camera.pitch=12", L"clouds.cloudiness=0.35"}},
        {"above", {}},
        {"inside", {L"camera.position=0,3000,0", L"camera.yaw=30", L"camera.pitch=5"}},
        {"behind", {L"camera.position=0,2000,0", L"camera.yaw=-160", L"camera.pitch=-5"}}};
    for (const auto& [name, view] : views) {
        const std::vector<float> culled = capture("cull-" + name, plus(view, {L"clouds.visibilityCulling=on"}));
        const std::vector<float> all = capture("all-" + name, plus(view, {L"clouds.visibilityCulling=off"}));
        ASSERT_FALSE(culled.empty()) << name;
        EXPECT_TRUE(allFinite(culled)) << name;
        EXPECT_EQ(culled, all) << name;
    }
}

// Light terms (docs/clouds.md, "Against the reference"): the sunlight scattered once, the
// sunlight scattered more than once and the sky's light, each drawn alone through the same
// opacity and aerial perspective, add up to the whole plus twice the clouds with no light of their
// own (None: what the haze in front and the scene behind give), value for value to the rounding
// of the EXR's half floats, and in the frame's mean to 1e-4; and each term is light the clouds
// have (brighter than None).
TEST(CloudCapture, TheLightTermsAddUpToTheCloudsLight) {
    const std::vector<std::wstring> view{L"camera.position=0,1500,0", L"camera.yaw=30", L"camera.pitch=12", L"clouds.cloudiness=0.35"};
    const std::vector<float> all = capture("terms-all", plus(view, {L"clouds.lightTerms=All"}));
    const std::vector<float> once = capture("terms-once", plus(view, {L"clouds.lightTerms=Sun, scattered once"}));
    const std::vector<float> more = capture("terms-more", plus(view, {L"clouds.lightTerms=Sun, scattered more than once"}));
    const std::vector<float> sky = capture("terms-sky", plus(view, {L"clouds.lightTerms=Sky"}));
    const std::vector<float> none = capture("terms-none", plus(view, {L"clouds.lightTerms=None"}));
    for (const std::vector<float>* v : {&all, &once, &more, &sky, &none}) {
        ASSERT_EQ(v->size(), all.size());
        ASSERT_FALSE(v->empty());
        EXPECT_TRUE(allFinite(*v));
    }
    double worst = 0.0, sumAll = 0.0, sumOnce = 0.0, sumMore = 0.0, sumSky = 0.0, sumNone = 0.0;
    for (size_t i = 0; i < all.size(); ++i) {
        const double whole = static_cast<double>(all[i]) + 2.0 * none[i];
        const double terms = static_cast<double>(once[i]) + more[i] + sky[i];
        worst = std::max(worst, std::abs(terms - whole) / (whole + 1e-4));
        sumAll += all[i], sumOnce += once[i], sumMore += more[i], sumSky += sky[i], sumNone += none[i];
    }
    const double meanRatio = (sumOnce + sumMore + sumSky) / (sumAll + 2.0 * sumNone);
    std::printf("light terms: mean all %.4g, once %.4g, more than once %.4g, sky %.4g, none %.4g; the terms over the whole %.6f, worst value %.2e\n",
                sumAll / all.size(), sumOnce / all.size(), sumMore / all.size(), sumSky / all.size(), sumNone / all.size(), meanRatio, worst);
    // A half float keeps 11 bits: each value rounds by up to 2^-11 of itself, so the five values'
    // sums differ by up to 2 x 2^-11 = 1e-3 of the whole (measured 1.3e-3 with the blending's own
    // rounding); a term lost or counted twice is a few percent.
    EXPECT_LT(worst, 2.5e-3);
    EXPECT_NEAR(meanRatio, 1.0, 1e-4);
    EXPECT_GT(sumOnce, sumNone * 1.001);
    EXPECT_GT(sumMore, sumNone * 1.001);
    EXPECT_GT(sumSky, sumNone * 1.001);
}

// The path-traced reference in strides (Reference pixel stride; docs/clouds.md, "Path-traced
// reference"): a round of stride^2 passes draws the very paths one pass at stride 1 draws, value
// for value; half a round has traced its pixels as the full pass does, and shows each pixel whose
// turn has not come as its block's first pixel (equal to it wherever that pixel's one path did
// not reach the scene behind the clouds).
TEST(CloudCapture, TheReferenceInStridesDrawsTheFullPassAfterARound) {
    constexpr int kSide = 2, kW = 48, kH = 27;
    const auto traced = [](const std::string& name, int stride, int frames) {
        const std::vector<std::wstring> settings{L"camera.position=0,8000,0", L"camera.pitch=-30", L"sun.elevation=35",
                                                 L"clouds.renderer=Reference (path traced)", L"clouds.referenceStride=" + std::to_wstring(stride)};
        return captureRadiance(std::filesystem::temp_directory_path() / "firmament-clouds", name, settings, kW, kH, frames);
    };
    const std::vector<float> full = traced("reference-stride-1", 1, 1);
    const std::vector<float> round = traced("reference-stride-2-round", kSide, kSide * kSide);
    const std::vector<float> half = traced("reference-stride-2-half", kSide, kSide);
    ASSERT_FALSE(full.empty());
    ASSERT_FALSE(round.empty());
    ASSERT_FALSE(half.empty());
    EXPECT_TRUE(allFinite(full));
    EXPECT_EQ(round, full);
    // The first two passes traced the even rows.
    const auto pixel = [](const std::vector<float>& image, int x, int y) {
        const size_t i = (static_cast<size_t>(y) * kW + x) * 3;
        return std::array<float, 3>{image[i], image[i + 1], image[i + 2]};
    };
    int tracedDiffer = 0, waiting = 0, waitingAsFirst = 0, notFinite = 0;
    for (int y = 0; y < kH; ++y)
        for (int x = 0; x < kW; ++x) {
            if (y % kSide == 0) {
                tracedDiffer += pixel(half, x, y) != pixel(full, x, y);
                continue;
            }
            ++waiting;
            const std::array<float, 3> shown = pixel(half, x, y);
            waitingAsFirst += shown == pixel(half, x - x % kSide, y - y % kSide);
            for (float v : shown) notFinite += !std::isfinite(v) || v < 0.0f;
        }
    EXPECT_EQ(tracedDiffer, 0);
    EXPECT_EQ(notFinite, 0);
    // From above at the default cloudiness most paths end in the clouds.
    EXPECT_GT(waitingAsFirst, waiting / 3) << waiting;
}

// Downscale (docs/clouds.md, "Low-resolution rendering"): at 2x and 4x the clouds keep their
// light on the whole, and the terrain the clouds do not cover keeps its own, but for the pixels
// along its silhouette.
TEST(CloudCapture, DownscaleKeepsTheCloudsAndTheTerrainsEdges) {
    const std::vector<std::wstring> view{L"camera.position=0,1500,0", L"camera.pitch=4", L"camera.yaw=-60", L"clouds.cloudiness=0.5",
                                         L"clouds.shadows=off"};
    const std::vector<float> clear = capture("downscale-clear", plus(view, {L"clouds.enabled=off"}));
    const std::vector<float> full = capture("downscale-1x", plus(view, {L"clouds.downscale=1x"}));
    ASSERT_FALSE(full.empty());
    for (const wchar_t* setting : {L"clouds.downscale=2x", L"clouds.downscale=4x"}) {
        const std::string name(setting + std::wcslen(L"clouds.downscale="), setting + std::wcslen(setting));
        const std::vector<float> low = capture("downscale-" + name, plus(view, {setting}));
        ASSERT_EQ(low.size(), full.size()) << name;
        EXPECT_TRUE(allFinite(low)) << name;
        // Where the clouds leave the frame as it was at full resolution (the terrain and sky they do
        // not cover), farther than the factor's pixels from any they cover, the low resolution
        // leaves it too: the clouds behind the mountains stay cut at their silhouettes.
        const int factor = name == "2x" ? 2 : 4;
        auto covered = [&](int x, int y) {
            for (int c = 0; c < 3; ++c) {
                const size_t i = (static_cast<size_t>(y) * kWidth + x) * 3 + c;
                if (std::abs(full[i] - clear[i]) > 1e-4f * std::abs(clear[i]) + 1e-7f) return true;
            }
            return false;
        };
        size_t uncovered = 0, changed = 0;
        for (int y = 0; y < kHeight; ++y)
            for (int x = 0; x < kWidth; ++x) {
                bool nearClouds = false;
                for (int dy = -factor; dy <= factor && !nearClouds; ++dy)
                    for (int dx = -factor; dx <= factor && !nearClouds; ++dx)
                        nearClouds = covered(std::clamp(x + dx, 0, kWidth - 1), std::clamp(y + dy, 0, kHeight - 1));
                if (nearClouds) continue;
                ++uncovered;
                for (int c = 0; c < 3; ++c) {
                    const size_t i = (static_cast<size_t>(y) * kWidth + x) * 3 + c;
                    changed += std::abs(low[i] - clear[i]) > 0.01f * std::abs(clear[i]) + 1e-6f;
                }
            }
        const double cloudShare = changedShare(clear, full);
        std::printf("%s: values the clouds change %.1f%%; of the %zu pixels away from them, %zu values changed at low resolution; mean %.4f against %.4f at 1x\n",
                    name.c_str(), 100.0 * cloudShare, uncovered, changed, mean(low), mean(full));
        EXPECT_GT(cloudShare, 0.1) << name;
        EXPECT_GT(uncovered, static_cast<size_t>(kWidth * kHeight / 10)) << name;
        EXPECT_EQ(changed, 0u) << name;
        EXPECT_NEAR(mean(low) / mean(full), 1.0, 0.03) << name;
    }
}

// Light occlusion (docs/clouds.md): seen from below, the particles under others are lit through
// them, so the clouds overhead are darker with it than without; every map resolution is finite.
// Measured 0.916 since deck diffusion (the deck's diffuse light falls slowly with the column's
// depth; 0.48 before it, 0.31 before the scaled transmittance); with the columns lost it is 1.
TEST(CloudCapture, LightOcclusionDarkensTheCloudsFromBelow) {
    const std::vector<std::wstring> below{L"camera.position=0,1500,0", L"camera.pitch=25", L"clouds.cloudiness=0.8", L"sun.elevation=50"};
    const std::vector<float> unoccluded = capture("occlusion-off", plus(below, {L"clouds.lightOcclusion=off"}));
    const std::vector<float> occluded = capture("occlusion-on", plus(below, {L"clouds.lightOcclusion=on"}));
    ASSERT_FALSE(unoccluded.empty());
    ASSERT_EQ(occluded.size(), unoccluded.size());
    const double ratio = mean(occluded) / mean(unoccluded);
    std::printf("the clouds from below with light occlusion: %.3f of their radiance without\n", ratio);
    EXPECT_LT(ratio, 0.95);
    EXPECT_GT(ratio, 0.2);
    for (const wchar_t* resolution : {L"clouds.lightSpaceResolution=256", L"clouds.lightSpaceResolution=2048"}) {
        const std::vector<float> frame = capture("occlusion-map", plus(below, {resolution}));
        EXPECT_TRUE(allFinite(frame)) << std::string(resolution, resolution + std::wcslen(resolution));
        EXPECT_LT(mean(frame) / mean(unoccluded), 0.95) << std::string(resolution, resolution + std::wcslen(resolution));
    }
}

TEST(CloudCapture, ShadedCloudsAreFiniteFromTheGroundToOrbitAtNoonSunsetAndNight) {
    const wchar_t* const places[] = {L"camera.position=0,200,0", L"camera.position=0,3000,0", L"camera.position=0,9000,0",
                                     L"camera.position=0,400000,0"};
    const wchar_t* const suns[] = {L"sun.elevation=60", L"sun.elevation=2", L"sun.elevation=-10"};
    int index = 0;
    for (const wchar_t* place : places)
        for (const wchar_t* sun : suns) {
            const std::vector<float> frame = capture("sweep-" + std::to_string(index++), {place, sun, L"camera.pitch=-10", L"clouds.enabled=on"});
            EXPECT_TRUE(allFinite(frame)) << std::string(place, place + std::wcslen(place)) << " " << std::string(sun, sun + std::wcslen(sun));
            EXPECT_FALSE(frame.empty());
        }
}

TEST(CloudCapture, ShadedCloudsAreFiniteAtEveryControlsExtremes) {
    int index = 100;
    const wchar_t* const extremes[] = {L"clouds.altitude=10000", L"clouds.thickness=100", L"clouds.thickness=1500", L"clouds.maxLayers=16",
                                       L"clouds.rings=1", L"clouds.ringDimension=16", L"clouds.particleDistance=500000", L"clouds.speed=2",
                                       L"clouds.particleDensity=Pyroclastic"};
    for (const wchar_t* extreme : extremes) {
        const std::vector<float> frame = capture("extreme-" + std::to_string(index++), {extreme, L"clouds.enabled=on", L"clouds.cloudiness=1"});
        EXPECT_TRUE(allFinite(frame)) << std::string(extreme, extreme + std::wcslen(extreme));
    }
}

}  // namespace
}  // namespace firmament::test
