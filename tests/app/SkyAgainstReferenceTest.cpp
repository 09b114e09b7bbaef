// Each atmosphere model's sky against the reference atmosphere in three views of the scoring grid
// (tools/score-atmospheres, docs/atmosphere.md "Scores"): captured as the tool captures them (a
// wide view, the ground black, no terrain, grid, clouds or light shafts) and scored at the same
// 8 x 6 pixels (the views of the sky only) against the reference's light of every order, traced
// at 256 paths a pixel as the tool traces it (with seeds of its own: the reference's noise, a
// few percent, is in the bounds). Each model's median and 95th-percentile relative error of the
// luminance are held to bounds a little above what was measured here and by the tool.
#include "atmosphere/AtmosphereParameters.h"
#include "atmosphere/AtmosphereSettings.h"
#include "core/ExrImage.h"
#include "support/HeadlessCapture.h"
#include "support/SkyScore.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cstdio>
#include <filesystem>
#include <string>
#include <vector>

namespace firmament::test {
namespace {

struct ModelBounds {
    const char* model;
    double median, p95;  // relative error of the luminance
};

struct SkyView {
    const char* name;
    double altitude, sunElevation;
    std::vector<ModelBounds> bounds;
};

class SkyAgainstReference : public ::testing::TestWithParam<SkyView> {};

TEST_P(SkyAgainstReference, EachModelsSkyIsWithinItsMeasuredError) {
    const SkyView v = GetParam();
    const auto folder = std::filesystem::temp_directory_path() / (std::string("firmament-sky-reference-") + v.name);
    std::filesystem::remove_all(folder);
    std::vector<FloatExrFile> captures;
    for (const ModelBounds& b : v.bounds) {
        HeadlessCapture c;
        c.fragment = {{"scene", {{"orientationGrid", false}}},
                      {"terrain", {{"enabled", false}}},
                      {"clouds", {{"enabled", false}}},
                      {"lightShafts", {{"enabled", false}}},
                      {"sun", {{"elevation", v.sunElevation}, {"azimuth", 0}}},
                      {"atmosphere", {{"model", b.model}, {"groundAlbedo", 0.0}}},
                      {"camera", {{"position", {0, v.altitude, 0}}, {"yaw", 40}, {"pitch", 10}, {"fieldOfView", 90}}}};
        c.width = 64;
        c.height = 40;
        c.png = folder / (std::string(b.model).substr(0, 5) + ".png");
        const ProcessResult run = captureHeadless(c);
        ASSERT_EQ(run.exitCode, 0u) << run.output;
        captures.push_back(readFloatExr(std::filesystem::path(c.png).replace_extension(".exr")));
    }
    const atmosphere::ReferenceAtmosphere reference(AtmosphereParameters::from(AtmosphereSettings{}));
    const glm::dvec3 camera(0.0, reference.parameters().earthRadius + v.altitude, 0.0);
    std::vector<PixelRay> rays = sampledRays(captures[0], 8, 6, 3.0 * 3.14159265358979323846 / 180.0);
    std::erase_if(rays, [&](const PixelRay& r) { return reference.hitsGround(camera, r.direction); });
    ASSERT_GT(rays.size(), 20u);
    std::vector<glm::dvec3> expected;
    for (size_t i = 0; i < rays.size(); ++i)
        expected.push_back(referenceRadiance(reference, camera, rays[i].direction, directionToSun(captures[0]), 256, 7000u + static_cast<unsigned>(i)).mean);
    for (size_t m = 0; m < v.bounds.size(); ++m) {
        std::vector<glm::dvec3> got;
        for (const PixelRay& r : rays) got.push_back(capturedRadiance(captures[m], r.x, r.y));
        const SkyScore s = scoreSky(got, expected);
        std::printf("%s, %s: median %.4f, 95th percentile %.4f, HDR PSNR %.1f dB over %zu pixels\n", v.name, v.bounds[m].model, s.medianRelativeError,
                    s.p95RelativeError, s.hdrPsnrDb, s.pixels);
        EXPECT_LT(s.medianRelativeError, v.bounds[m].median) << v.bounds[m].model;
        EXPECT_LT(s.p95RelativeError, v.bounds[m].p95) << v.bounds[m].model;
    }
    std::filesystem::remove_all(folder);
}

INSTANTIATE_TEST_SUITE_P(
    ThreeViews, SkyAgainstReference,
    // Measured here (median / 95th percentile): from the ground, the sun 20 degrees up, Yusov
    // 4.9% / 28%, Bruneton 4.5% / 35%, Hillaire 3.3% / 32% (the worst pixels graze the horizon);
    // from 10 km, the sun 5 degrees up, 1.7% / 7.9%, 1.2% / 3.4%, 1.5% / 4.8%; from 40 km at
    // noon, 3.5% / 7.2%, 2.5% / 4.7%, 1.7% / 4.5%.
    ::testing::Values(SkyView{"ground-sun20", 2.0, 20.0, {{"Yusov 2013", 0.075, 0.38}, {"Bruneton 2008", 0.07, 0.47}, {"Hillaire 2020", 0.06, 0.43}}},
                      SkyView{"10km-sun5", 10000.0, 5.0, {{"Yusov 2013", 0.035, 0.12}, {"Bruneton 2008", 0.03, 0.065}, {"Hillaire 2020", 0.035, 0.08}}},
                      SkyView{"40km-sun60", 40000.0, 60.0, {{"Yusov 2013", 0.06, 0.11}, {"Bruneton 2008", 0.05, 0.08}, {"Hillaire 2020", 0.04, 0.08}}}),
    [](const ::testing::TestParamInfo<SkyView>& param) {
        std::string name = param.param.name;
        std::replace(name.begin(), name.end(), '-', '_');
        return name;
    });

}  // namespace
}  // namespace firmament::test
