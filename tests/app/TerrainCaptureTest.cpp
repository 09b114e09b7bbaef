// The terrain in frames firmament.exe captures: the clipmap's levels meet without cracks (no
// background pixel below the horizon), nothing is NaN or Inf at any sun angle with either
// atmosphere model, and the terrain's views and the cascades' tint change the picture.
#include "core/ExrImage.h"
#include "support/CaptureRadiance.h"
#include "support/HeadlessCapture.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <string>
#include <vector>

namespace firmament::test {
namespace {

constexpr int kWidth = 320, kHeight = 180;
constexpr double kEarthRadius = 6360e3;
constexpr float kBackground[3] = {0.02f, 0.025f, 0.035f};  // the HDR frame's clear value (src/app/App.cpp)

std::filesystem::path scratch(const std::string& name) {
    const auto folder = std::filesystem::temp_directory_path() / ("firmament-terrain-" + name);
    std::filesystem::remove_all(folder);
    return folder;
}

// One headless frame with the given --set assignments; its HDR capture.
ExrFile captureFrame(const std::string& name, const std::vector<std::wstring>& settings) {
    const auto folder = scratch(name);
    HeadlessCapture capture;
    capture.settings = {L"clouds.enabled=off"};  // the terrain alone under the atmosphere: no clouds in front of it
    capture.settings.insert(capture.settings.end(), settings.begin(), settings.end());
    capture.width = kWidth;
    capture.height = kHeight;
    capture.png = folder / "frame.png";
    const ProcessResult run = captureHeadless(capture);
    EXPECT_EQ(run.exitCode, 0u) << run.output;
    ExrFile file = readExr(folder / "frame.exr");
    std::filesystem::remove_all(folder);
    return file;
}

glm::vec3 pixel(const ExrFile& file, int x, int y) {
    glm::vec3 value;
    for (int ch = 0; ch < 3; ++ch) value[ch] = exrChannel(file, x, y, ch);
    return value;
}

bool isBackground(glm::vec3 v) {
    for (int ch = 0; ch < 3; ++ch)
        if (std::abs(v[ch] - kBackground[ch]) > 1e-4f) return false;
    return true;
}

// The world direction of each pixel's ray and the camera's altitude, from a capture's header.
struct CapturedRays {
    explicit CapturedRays(const ExrFile& file) {
        const glm::mat4 view = std::get<glm::mat4>(file.attributes.at("firmament.view"));
        camera = glm::vec3(glm::inverse(view)[3]);
        glm::mat4 rotation = view;
        rotation[3] = glm::vec4(0.0f, 0.0f, 0.0f, 1.0f);
        clipToDirection = glm::inverse(std::get<glm::mat4>(file.attributes.at("firmament.projection")) * rotation);
    }
    glm::dvec3 direction(int x, int y) const {
        const glm::vec4 ndc((x + 0.5f) / kWidth * 2.0f - 1.0f, 1.0f - (y + 0.5f) / kHeight * 2.0f, 1.0f, 1.0f);
        const glm::vec4 farPoint = clipToDirection * ndc;
        return glm::normalize(glm::dvec3(farPoint) / static_cast<double>(farPoint.w));
    }
    // Distance along a ray to the sea-level sphere (centre (0, -R, 0)), or a negative value.
    double distanceToSeaLevel(glm::dvec3 direction) const {
        const glm::dvec3 fromCentre = glm::dvec3(camera) + glm::dvec3(0.0, kEarthRadius, 0.0);
        const double b = glm::dot(fromCentre, direction), c = glm::dot(fromCentre, fromCentre) - kEarthRadius * kEarthRadius;
        const double discriminant = b * b - c;
        return discriminant < 0.0 ? -1.0 : -b - std::sqrt(discriminant);
    }
    // The horizon's dip below the horizontal for the camera's altitude (slightly overestimated).
    double horizonDip() const { return std::sqrt(2.0 * std::max(static_cast<double>(camera.y), 1.0) / kEarthRadius); }

    glm::vec3 camera{};
    glm::mat4 clipToDirection{};
};

struct View {
    const char* name;
    std::vector<std::wstring> camera;
};

// Over the clear colour, without the atmosphere or the grid: every pixel whose ray points below
// the horizon (the geometric dip for the camera's altitude, and half a degree more) must be
// terrain. The terrain stands on or above the sea-level sphere and its coarsest level reaches
// 4,194 km, beyond the horizon from up to 1,000 km, so a background pixel there is a crack or the
// terrain's end.
TEST(TerrainCapture, LevelsMeetWithoutCracks) {
    const std::vector<View> views = {
        {"ground", {L"camera.position=0,0,0", L"camera.pitch=-30"}},  // pushed up to 100 m above the ground
        {"valley", {L"camera.position=5000,1500,-3000", L"camera.yaw=40", L"camera.pitch=-10"}},
        {"default", {L"camera.position=0,8000,0", L"camera.pitch=-20"}},
        {"far", {L"camera.position=-12345,300,777", L"camera.yaw=-160", L"camera.pitch=-4"}},
        {"high", {L"camera.position=30000,20000,-50000", L"camera.yaw=120", L"camera.pitch=-45"}},
        {"demo's end", {L"camera.position=9000,40000,9000", L"camera.yaw=80", L"camera.pitch=-12"}},
        {"orbit", {L"camera.position=0,400000,0", L"camera.pitch=-30"}},  // the horizon 2,260 km away
    };
    for (const View& v : views) {
        std::vector<std::wstring> settings{L"atmosphere.enabled=off", L"scene.orientationGrid=off", L"shadows.enabled=off"};
        settings.insert(settings.end(), v.camera.begin(), v.camera.end());
        const ExrFile file = captureFrame(std::string("cracks-") + v.name, settings);
        const CapturedRays rays(file);
        const glm::vec3 camera = rays.camera;
        const double dip = rays.horizonDip() + glm::radians(0.5);
        int below = 0, cracks = 0;
        for (int y = 0; y < kHeight; ++y)
            for (int x = 0; x < kWidth; ++x) {
                const glm::dvec3 direction = rays.direction(x, y);
                if (direction.y > -std::sin(dip)) continue;
                ++below;
                if (isBackground(pixel(file, x, y))) {
                    if (++cracks <= 10) ADD_FAILURE() << v.name << ": background at pixel " << x << ", " << y;
                }
            }
        std::printf("view %s: camera at %.0f, %.0f, %.0f; %d pixels below the horizon, %d of them background\n", v.name, camera.x, camera.y,
                    camera.z, below, cracks);
        EXPECT_GT(below, kWidth * kHeight / 10) << v.name << ": the view should look down on the terrain";
        EXPECT_EQ(cracks, 0) << v.name;
    }
}

// Under light scattering the orientation grid draws the Earth's sphere with depth. The terrain's
// plains lie within metres of it, closer than the depth buffer resolves from afar, so the grid
// must start where the terrain ends: with the terrain filling the view, the frame is the same
// with the grid on or off.
TEST(TerrainCapture, TheGridStaysBeyondTheTerrain) {
    const std::vector<std::wstring> view{L"camera.position=6000,40000,9000", L"camera.yaw=120", L"camera.pitch=-60", L"shadows.enabled=off"};
    std::vector<std::wstring> withGrid = view, withoutGrid = view;
    withGrid.push_back(L"scene.orientationGrid=on");
    withoutGrid.push_back(L"scene.orientationGrid=off");
    const ExrFile a = captureFrame("grid-on", withGrid), b = captureFrame("grid-off", withoutGrid);
    int differing = 0;
    for (int y = 0; y < kHeight; ++y)
        for (int x = 0; x < kWidth; ++x)
            if (pixel(a, x, y) != pixel(b, x, y)) ++differing;
    EXPECT_EQ(differing, 0) << "pixels where the grid shows through the terrain";
}

// Where the terrain ends, nothing may show: seen from 400 km and from 40 km, with the atmosphere
// and the orientation grid on, the mean luminance of each row of pixels well below the horizon
// (2 degrees or more) and over 100 km away (where single mountains no longer fill a row) changes
// smoothly from row to row. A hard edge (the terrain's square against the grid's sphere, as
// before the clipmap reached the horizon) steps the rows it crosses.
TEST(TerrainCapture, NoHardEdgeWhereTheTerrainEnds) {
    const std::vector<View> views = {
        {"orbit", {L"camera.position=0,400000,0", L"camera.pitch=-30"}},
        {"stratosphere", {L"camera.position=0,40000,0", L"camera.pitch=-12"}},
    };
    for (const View& v : views) {
        std::vector<std::wstring> settings{L"sun.elevation=40", L"sun.azimuth=30", L"scene.orientationGrid=on"};
        settings.insert(settings.end(), v.camera.begin(), v.camera.end());
        const ExrFile file = captureFrame(std::string("edge-") + v.name, settings);
        const CapturedRays rays(file);
        const double limit = -std::sin(rays.horizonDip() + glm::radians(2.0));
        std::vector<double> rowMeans;
        for (int y = 0; y < kHeight; ++y) {
            double sum = 0.0;
            int count = 0;
            for (int x = 0; x < kWidth; ++x) {
                const glm::dvec3 direction = rays.direction(x, y);
                if (direction.y > limit || rays.distanceToSeaLevel(direction) < 100e3) continue;
                const glm::vec3 c = pixel(file, x, y);
                sum += 0.2126 * c.r + 0.7152 * c.g + 0.0722 * c.b;
                ++count;
            }
            if (count == kWidth) rowMeans.push_back(sum / count);
        }
        ASSERT_GT(rowMeans.size(), static_cast<size_t>(kHeight / 4)) << v.name << ": the view should look down on distant terrain";
        double largest = 0.0;
        for (size_t r = 1; r < rowMeans.size(); ++r) {
            largest = std::max(largest, std::abs(rowMeans[r] - rowMeans[r - 1]) / std::max(rowMeans[r], rowMeans[r - 1]));
        }
        std::printf("view %s: %zu rows below the horizon, largest step of a row's mean luminance %.2f%%\n", v.name, rowMeans.size(),
                    100.0 * largest);
        EXPECT_LT(largest, 0.05) << v.name;
    }
}

TEST(TerrainCapture, NoNanOrInfAtAnySunAngle) {
    for (const wchar_t* model : {L"Yusov 2013", L"Bruneton 2008"})
        for (const int elevation : {-8, -1, 0, 2, 15, 90}) {
            const ExrFile file = captureFrame("finite", {L"camera.position=2000,2500,-4000", L"camera.pitch=-12", L"camera.yaw=30",
                                                         L"sun.elevation=" + std::to_wstring(elevation), L"sun.azimuth=60",
                                                         std::wstring(L"atmosphere.model=") + model});
            int bad = 0;
            for (int y = 0; y < kHeight; ++y)
                for (int x = 0; x < kWidth; ++x) {
                    const glm::vec3 v = pixel(file, x, y);
                    if (!std::isfinite(v.r) || !std::isfinite(v.g) || !std::isfinite(v.b)) ++bad;
                }
            EXPECT_EQ(bad, 0) << "model " << (model[0] == L'Y' ? "Yusov" : "Bruneton") << ", sun at " << elevation << " degrees";
        }
}

// The terrain's pixels end to end, against Yusov 2013's shading computed on the CPU from the
// same frame's albedo and normal views. Scattering and shadows off, so the sun arrives
// unattenuated (T = 1) and the sky gives its constant 0.1 (ground_lighting.hlsli, model 0):
//   L = albedo / pi * (max(N . L, 0) T_clouds + 0.1 * saturate(4 cos(sun zenith) + 0.25) * (1 + N . up) / 2),
// T_clouds = 1 without clouds, else the "Cloud shadows" view's. The view stays within 10 km of
// the origin, where the local vertical is (0, 1, 0) to 0.1 degree. Returns the transmittances.
std::vector<double> expectShadingFormula(const std::string& name, const std::vector<std::wstring>& extra, bool clouds) {
    std::vector<std::wstring> view{L"camera.position=1500,2600,-2000", L"camera.pitch=-35", L"camera.yaw=20", L"sun.elevation=28",
                                   L"sun.azimuth=-70", L"atmosphere.enabled=off", L"scene.orientationGrid=off", L"shadows.enabled=off"};
    view.insert(view.end(), extra.begin(), extra.end());
    const auto with = [&](const wchar_t* more) {
        std::vector<std::wstring> v = view;
        v.push_back(more);
        return v;
    };
    const ExrFile shaded = captureFrame(name + "-shaded", with(L"terrain.view=shaded"));
    const ExrFile albedo = captureFrame(name + "-albedo", with(L"terrain.view=albedo"));
    const ExrFile normals = captureFrame(name + "-normals", with(L"terrain.view=normals"));
    const ExrFile cloudShadows = clouds ? captureFrame(name + "-clouds", with(L"terrain.view=Cloud shadows")) : ExrFile{};
    const glm::dvec3 toSun(std::get<glm::vec3>(shaded.attributes.at("firmament.directionToSun")));
    const double pi = 3.14159265358979323846;
    const double sky = 0.1 * std::clamp(4.0 * toSun.y + 0.25, 0.0, 1.0);
    int compared = 0, wrong = 0;
    double largest = 0.0;
    std::vector<double> transmittances;
    for (int y = 0; y < kHeight; ++y)
        for (int x = 0; x < kWidth; ++x) {
            const glm::vec3 a = pixel(albedo, x, y);
            if (isBackground(a)) continue;
            ++compared;
            const glm::dvec3 n = glm::normalize(glm::dvec3(pixel(normals, x, y)) * 2.0 - 1.0);
            const double transmittance = clouds ? static_cast<double>(pixel(cloudShadows, x, y).x) : 1.0;
            transmittances.push_back(transmittance);
            const double light = std::max(glm::dot(n, toSun), 0.0) * transmittance + sky * std::clamp((1.0 + n.y) * 0.5, 0.0, 1.0);
            const glm::dvec3 expected = glm::dvec3(a) / pi * light;
            const glm::dvec3 got(pixel(shaded, x, y));
            for (int ch = 0; ch < 3; ++ch) {
                // Relative to albedo / pi: half floats carry 11 bits, and the albedo, the normal,
                // the transmittance and the result each round.
                const double error = std::abs(got[ch] - expected[ch]) / (glm::dvec3(a)[ch] / pi);
                largest = std::max(largest, error);
                if (error > 0.01 && ++wrong <= 5)
                    ADD_FAILURE() << name << ": pixel " << x << ", " << y << " channel " << ch << ": " << got[ch] << " against " << expected[ch];
            }
        }
    std::printf("%s: terrain pixels against the shading formula: %d compared, largest error %.5f of albedo / pi\n", name.c_str(), compared, largest);
    EXPECT_GT(compared, kWidth * kHeight / 2) << name;
    EXPECT_EQ(wrong, 0) << name;
    return transmittances;
}

TEST(TerrainCapture, ShadedPixelsFollowTheShadingFormula) {
    expectShadingFormula("formula", {}, false);
}

// The clouds' shadows on the ground (Yusov 2014): each pixel's sun term times the clouds'
// transmittance at it, which the "Cloud shadows" view shows (its values against the particles
// themselves: CloudParticlesTest). The clouds need the atmosphere to be drawn; their shadows do
// not. Broken clouds: some ground in their shadow, some in the sun.
TEST(TerrainCapture, CloudShadowsDarkenTheSunsTermByTheCloudsTransmittance) {
    const std::vector<double> t = expectShadingFormula("clouds", {L"clouds.enabled=on", L"clouds.cloudiness=0.35"}, true);
    ASSERT_FALSE(t.empty());
    const auto share = [&](auto predicate) { return static_cast<double>(std::count_if(t.begin(), t.end(), predicate)) / static_cast<double>(t.size()); };
    const double shadowed = share([](double v) { return v < 0.5; }), lit = share([](double v) { return v > 0.95; });
    const double outside = share([](double v) { return !(v >= 0.0 && v <= 1.0); });
    std::printf("cloud shadows: %.2f of the ground below transmittance 0.5, %.2f above 0.95\n", shadowed, lit);
    EXPECT_EQ(outside, 0.0) << "a transmittance outside [0, 1]";
    EXPECT_GT(shadowed, 0.1);
    EXPECT_GT(lit, 0.1);
    // "Cloud shadows" off: none.
    const std::vector<double> off = expectShadingFormula("no-cloud-shadows", {L"clouds.enabled=on", L"clouds.cloudiness=0.35", L"clouds.shadows=off"}, true);
    EXPECT_EQ(std::count(off.begin(), off.end(), 1.0), static_cast<std::ptrdiff_t>(off.size()));
}

// The share of pixels that differ by more than 1% between two frames.
double changedShare(const ExrFile& a, const ExrFile& b) {
    int changed = 0;
    for (int y = 0; y < kHeight; ++y)
        for (int x = 0; x < kWidth; ++x) {
            const glm::vec3 u = pixel(a, x, y), v = pixel(b, x, y);
            if (glm::length(u - v) > 0.01f * std::max(glm::length(u), 1e-3f)) ++changed;
        }
    return static_cast<double>(changed) / (kWidth * kHeight);
}

TEST(TerrainCapture, ViewsShadowsAndCascadeTintChangeThePicture) {
    const std::vector<std::wstring> scene{L"camera.position=0,3500,0", L"camera.pitch=-15", L"sun.azimuth=90", L"sun.elevation=12"};
    const auto with = [&](std::vector<std::wstring> extra) {
        extra.insert(extra.begin(), scene.begin(), scene.end());
        return extra;
    };
    const ExrFile shaded = captureFrame("shaded", scene);
    const ExrFile unshadowed = captureFrame("unshadowed", with({L"shadows.enabled=off"}));
    const ExrFile tinted = captureFrame("tinted", with({L"shadows.showCascades=on"}));
    const ExrFile albedo = captureFrame("albedo", with({L"terrain.view=albedo"}));
    const ExrFile levels = captureFrame("levels", with({L"terrain.view=clipmap levels"}));
    const ExrFile noTerrain = captureFrame("none", with({L"terrain.enabled=off"}));
    const double shadowed = changedShare(shaded, unshadowed);
    std::printf("pixels changed: by shadows %.3f, by the cascade tint %.3f, albedo view %.3f, levels view %.3f, without terrain %.3f\n",
                shadowed, changedShare(shaded, tinted), changedShare(shaded, albedo), changedShare(shaded, levels),
                changedShare(shaded, noTerrain));
    EXPECT_GT(shadowed, 0.03);  // mountains cast shadows at a 12-degree sun
    EXPECT_LT(shadowed, 0.6);
    EXPECT_GT(changedShare(shaded, tinted), 0.3);
    EXPECT_GT(changedShare(shaded, albedo), 0.3);
    EXPECT_GT(changedShare(albedo, levels), 0.3);
    EXPECT_GT(changedShare(shaded, noTerrain), 0.3);
}

}  // namespace
}  // namespace firmament::test
