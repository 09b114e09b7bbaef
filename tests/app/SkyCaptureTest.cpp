// The sky in frames firmament.exe captures, against the CPU reference model: single
// scattering (multiple scattering off) along each sampled pixel's view ray, times the sun's
// intensity, for the sun high, low, at the horizon and below it (twilight), drawn by each model
// (Yusov 2013, Bruneton 2008). The EXR header gives the camera; the pixels'
// view rays are rebuilt from its matrices as the program builds them.
// Yusov's sky is held to the bounds twice: drawn by the atmosphere's own passes, per pixel, and
// by the light shafts' epipolar passes with nothing to cast a shadow (no terrain, no clouds),
// which must then draw the same sky.
#include "core/ExrImage.h"
#include "reference/ReferenceAtmosphere.h"
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

constexpr int kWidth = 96, kHeight = 64;
constexpr double kAltitude = 2.0;  // metres: the camera stands on the ground
// Integration's bounds (relative to each sample's own value). Measured here with the nodes placed
// by altitude and optical depth: medians 0.01% to 0.05% (0.02% to 0.11% with the light shafts),
// largest 0.18% to 0.60% (0.99% with them); with the nodes placed by altitude alone and the
// trapezoid rule, medians 0.10% to 0.42%, largest 1.4%. With uniform steps the cases from 1 km
// and 300 m failed: medians 5.7%, 0.85% and 0.25%, largest 31%, 26% and 12%.
constexpr double kIntegrationWorst = 0.015, kIntegrationMedian = 0.002;
// With the light shafts, the ground under grazing rays: its distance changes by more than the
// refinement threshold (3%) from one pixel to the next, so no sample has the pixel's depth and
// the unwarping takes the light of the sample nearest in depth (docs/lightshafts.md,
// "Unwarping"). Measured: 2.8% at worst, 1.3 degrees under the horizon from 1 km; the sky's pixels
// keep Integration's own bounds.
constexpr double kShaftsGroundWorst = 0.04;

struct SkyCase {
    const wchar_t* model;  // atmosphere.model
    double sunElevation;  // degrees
    double tolerance;     // the largest error allowed for a sampled pixel, relative to the frame's brightest
    bool shafts = false;  // drawn by the light shafts' epipolar passes
};

class SkyCapture : public ::testing::TestWithParam<SkyCase> {};

// One headless frame of the sky alone (no terrain, no grid), single scattering only, with the
// camera `altitude` metres up and pitched `pitch` degrees; each sampled pixel's radiance beside
// the reference's along its view ray (the sun's disc and glare left out).
struct SkySample {
    glm::dvec3 captured, expected, viewDir;
};
std::vector<SkySample> captureSky(const std::string& tag, const std::vector<std::wstring>& settings, double altitude, double pitch,
                                  bool shafts, double fieldOfView = 70.0, int rowStep = 6) {
    const auto folder = std::filesystem::temp_directory_path() / ("firmament-sky-" + tag);
    std::filesystem::remove_all(folder);
    HeadlessCapture capture;
    capture.settings = {L"scene.orientationGrid=off", L"terrain.enabled=off", L"camera.position=0," + std::to_wstring(altitude) + L",0",
                        L"camera.pitch=" + std::to_wstring(pitch), L"camera.fieldOfView=" + std::to_wstring(fieldOfView), L"sun.azimuth=20", L"atmosphere.sunIntensity=2",
                        L"atmosphere.multipleScattering=none", L"atmosphere.scatteringOrders=1",
                        // The atmosphere's own passes, per pixel, or the light shafts' epipolar passes.
                        shafts ? L"lightShafts.enabled=on" : L"lightShafts.enabled=off", L"clouds.enabled=off"};
    capture.settings.insert(capture.settings.end(), settings.begin(), settings.end());
    // The light shafts' frames at 8 x the size (768 x 512), the grid's pixels at the same places:
    // the epipolar sampling (512 slices of 256 samples) then meets pixels as small as a real
    // frame's, 0.14 degrees. At 96 x 64 a pixel spans 1.1 degrees, and where the light changes
    // steeply with the angle (the ground near the horizon) the samples a pixel is blended from,
    // up to half a sample step away, differ from its own ray by 5 to 14%.
    const int scale = shafts ? 8 : 1;
    const int width = kWidth * scale, height = kHeight * scale;
    capture.width = width;
    capture.height = height;
    capture.png = folder / "sky.png";
    const ProcessResult run = captureHeadless(capture);
    EXPECT_EQ(run.exitCode, 0u) << run.output;
    if (run.exitCode != 0) return {};
    const ExrFile file = readExr(folder / "sky.exr");
    EXPECT_TRUE(file.attributes.count("firmament.atmosphere.parameters")) << "the physical constants are not in the header";

    const AtmosphereParameters p;  // the defaults the run used
    const atmosphere::ReferenceAtmosphere reference(p);
    glm::mat4 view = std::get<glm::mat4>(file.attributes.at("firmament.view"));
    view[3] = glm::vec4(0.0f, 0.0f, 0.0f, 1.0f);  // directions only
    const glm::mat4 clipToDirection = glm::inverse(std::get<glm::mat4>(file.attributes.at("firmament.projection")) * view);
    const glm::dvec3 sunDir(std::get<glm::vec3>(file.attributes.at("firmament.directionToSun")));
    const glm::dvec3 camera(0.0, p.earthRadius + altitude, 0.0);
    std::vector<SkySample> samples;
    for (int y0 = 2; y0 < kHeight; y0 += rowStep)
        for (int x0 = 3; x0 < kWidth; x0 += 9) {
            const int x = x0 * scale + scale / 2, y = y0 * scale + scale / 2;
            const glm::vec4 ndc((x + 0.5f) / width * 2.0f - 1.0f, 1.0f - (y + 0.5f) / height * 2.0f, 1.0f, 1.0f);
            const glm::vec4 farPoint = clipToDirection * ndc;
            const glm::dvec3 viewDir = glm::normalize(glm::dvec3(farPoint) / static_cast<double>(farPoint.w));
            if (glm::dot(viewDir, sunDir) > std::cos(glm::radians(3.0))) continue;  // the sun's disc and its glare
            glm::dvec3 captured;
            for (int ch = 0; ch < 3; ++ch) captured[ch] = exrChannel(file, x, y, ch);
            samples.push_back({captured, 2.0 * reference.singleScattering(camera, viewDir, sunDir), viewDir});
        }
    std::filesystem::remove_all(folder);
    return samples;
}

TEST_P(SkyCapture, SkyRadianceMatchesTheReference) {
    const SkyCase c = GetParam();
    const std::vector<SkySample> pairs =
        captureSky(std::to_string(c.model[0]) + std::to_string(static_cast<int>(std::round(c.sunElevation * 10.0))) + (c.shafts ? "s" : ""),
                   {L"sun.elevation=" + std::to_wstring(c.sunElevation), std::wstring(L"atmosphere.model=") + c.model}, kAltitude, 35.0, c.shafts);
    ASSERT_FALSE(pairs.empty());
    double brightest = 0.0, worst = 0.0, sum = 0.0;
    int samples = 0;
    for (const SkySample& s : pairs) brightest = std::max({brightest, s.expected.r, s.expected.g, s.expected.b});
    ASSERT_GT(brightest, 0.0);
    for (const auto& [captured, expected, viewDir] : pairs) {
        for (int ch = 0; ch < 3; ++ch) {
            const double error = std::abs(captured[ch] - expected[ch]) / brightest;
            worst = std::max(worst, error);
            sum += error;
            ++samples;
            EXPECT_LT(error, c.tolerance) << "view (" << viewDir.x << ", " << viewDir.y << ", " << viewDir.z << ") channel " << ch << ": "
                                          << captured[ch] << " vs " << expected[ch];
        }
    }
    std::printf("%ls%s, sun at %+.1f degrees: %d samples, error relative to the brightest %.4g: mean %.4f, largest %.4f\n", c.model,
                c.shafts ? " (light shafts)" : "", c.sunElevation,
                samples, brightest, sum / samples, worst);
    EXPECT_LT(sum / samples, c.tolerance / 3.0);
}

std::string caseName(const ::testing::TestParamInfo<SkyCase>& param) {
    const int tenths = static_cast<int>(std::round(param.param.sunElevation * 10.0));
    return std::string(param.param.model[0] == L'Y' ? "Yusov_" : "Bruneton_") + (tenths < 0 ? "minus" : "plus") + std::to_string(std::abs(tenths)) +
           "tenths" + (param.param.shafts ? "_shafts" : "");
}

INSTANTIATE_TEST_SUITE_P(SunElevations, SkyCapture,
                         // Measured here, Yusov: largest 9.7%, 5.5%, 5.1% and 1.6%; means 1.2% or
                         // less; the largest errors are near the zenith, where his 4D table is
                         // coarsest. Bruneton: largest 7.5%, 11%, 6.6% and 9.3%; means 0.9% or
                         // less; the largest are views 1.2 degrees above the horizon, which his
                         // u_mu (distance to the top over its largest value) resolves less finely
                         // than Yusov's eq. 5.
                         ::testing::Values(SkyCase{L"Yusov 2013", 45.0, 0.12}, SkyCase{L"Yusov 2013", 10.0, 0.08},
                                           SkyCase{L"Yusov 2013", 1.0, 0.08}, SkyCase{L"Yusov 2013", -3.0, 0.05},
                                           SkyCase{L"Yusov 2013", 45.0, 0.12, true}, SkyCase{L"Yusov 2013", 10.0, 0.08, true},
                                           SkyCase{L"Yusov 2013", 1.0, 0.08, true}, SkyCase{L"Yusov 2013", -3.0, 0.05, true},
                                           SkyCase{L"Bruneton 2008", 45.0, 0.12}, SkyCase{L"Bruneton 2008", 10.0, 0.13},
                                           SkyCase{L"Bruneton 2008", 1.0, 0.08}, SkyCase{L"Bruneton 2008", -3.0, 0.11}),
                         caseName);

// Single scattering by Integration (Yusov 2013's reference mode) at its default step count
// against the CPU reference, from the ground to 40 km, the sun high, low and at the horizon.
// Unlike the table, the integration has no interpolation to excuse: each sample is held to its
// own value (relative error, with a floor of 5% of the frame's brightest so that the darkest
// samples do not decide). Uniform steps failed this: 30 of them put one or two nodes in the
// aerosol layer of a rising ray, 6% off in the median and 31% at worst from 1 km; the nodes
// are now spaced geometrically away from the ray's low point
// (shaders/atmosphere/yusov/single_scattering.hlsli).
struct IntegrationCase {
    double altitude, sunElevation, pitch;
    bool shafts = false;  // drawn by the light shafts' epipolar passes
};

class IntegrationCapture : public ::testing::TestWithParam<IntegrationCase> {};

TEST_P(IntegrationCapture, ConvergesAtTheDefaultStepCount) {
    const IntegrationCase c = GetParam();
    const std::string tag = "int-" + std::to_string(static_cast<int>(c.altitude)) + "-" + std::to_string(static_cast<int>(c.sunElevation)) +
                            (c.shafts ? "s" : "");
    const std::vector<SkySample> pairs = captureSky(
        tag, {L"sun.elevation=" + std::to_wstring(c.sunElevation), L"atmosphere.singleScattering=Integration"}, c.altitude, c.pitch, c.shafts);
    ASSERT_FALSE(pairs.empty());
    double brightest = 0.0;
    for (const SkySample& s : pairs) brightest = std::max({brightest, s.expected.r, s.expected.g, s.expected.b});
    ASSERT_GT(brightest, 0.0);
    std::vector<double> errors;
    const double earthRadius = AtmosphereParameters{}.earthRadius;  // the defaults the run used
    const double horizonDip = std::acos(earthRadius / (earthRadius + c.altitude));
    for (const auto& [captured, expected, viewDir] : pairs)
        for (int ch = 0; ch < 3; ++ch) {
            const double error = std::abs(captured[ch] - expected[ch]) / std::max(expected[ch], 0.05 * brightest);
            errors.push_back(error);
            const bool ground = std::asin(viewDir.y) < -horizonDip;
            EXPECT_LT(error, c.shafts && ground ? kShaftsGroundWorst : kIntegrationWorst) << "view (" << viewDir.x << ", " << viewDir.y << ", " << viewDir.z << ") channel " << ch << ": "
                                                << captured[ch] << " vs " << expected[ch];
        }
    std::sort(errors.begin(), errors.end());
    const double median = errors[errors.size() / 2];
    std::printf("Integration%s from %.0f m, sun at %+.1f degrees: %zu samples, relative error median %.4f, largest %.4f\n",
                c.shafts ? " (light shafts)" : "", c.altitude, c.sunElevation, errors.size(), median, errors.back());
    EXPECT_LT(median, kIntegrationMedian);
}

INSTANTIATE_TEST_SUITE_P(AltitudesAndSunElevations, IntegrationCapture,
                         ::testing::Values(IntegrationCase{1000.0, 45.0, 35.0}, IntegrationCase{300.0, 10.0, 10.0},
                                           IntegrationCase{1000.0, 2.0, 5.0}, IntegrationCase{10000.0, 30.0, 0.0},
                                           IntegrationCase{40000.0, 20.0, -30.0}, IntegrationCase{1000.0, 45.0, 35.0, true},
                                           IntegrationCase{300.0, 10.0, 10.0, true}, IntegrationCase{1000.0, 2.0, 5.0, true},
                                           IntegrationCase{10000.0, 30.0, 0.0, true}, IntegrationCase{40000.0, 20.0, -30.0, true}),
                         [](const ::testing::TestParamInfo<IntegrationCase>& param) {
                             return std::to_string(static_cast<int>(param.param.altitude)) + "m_sun" + std::to_string(static_cast<int>(param.param.sunElevation)) +
                                    (param.param.shafts ? "_shafts" : "");
                         });

// Grazing rays by Integration, shafts off and on: narrow views (10 degrees high, every row
// sampled, 0.16 degrees apart) across the horizon, where the ray's lowest point lies hundreds of
// kilometres away behind an optical depth of several. Spacing the nodes by altitude alone put
// them there, and these cases failed: 5.0% off from 1 km, 9.7% from 40 km (40 dB), 12% at the
// horizon's dip (docs/atmosphere.md, "The integration's nodes"). The bound: each sample within 1%
// of the reference (no floor) and the samples together at least 50 dB, everywhere away from the
// 0.25-degree band around the horizon itself (0.125 degrees either side), whose worst is reported.
struct GrazingCase {
    double altitude, sunElevation, pitch;
    bool shafts = false;
};

// With the light shafts, the ground within 0.25 degrees under the horizon: the epipolar samples
// a pixel is interpolated from see a ground whose light changes steeply with the angle. Measured
// 1.3% there (from 1 km, sun 5 degrees, 0.18 degrees under the horizon) where the brute-force
// march of the same rays is within 0.18%: the march converges, the interpolation does not.
constexpr double kShaftsGroundNearHorizonWorst = 0.02;

void expectGrazingIntegrationConverges(const GrazingCase& c) {
    const std::string tag = "graze-" + std::to_string(static_cast<int>(c.altitude)) + "-" + std::to_string(static_cast<int>(c.sunElevation)) +
                            (c.shafts ? "s" : "");
    const std::vector<SkySample> pairs =
        captureSky(tag, {L"sun.elevation=" + std::to_wstring(c.sunElevation), L"atmosphere.singleScattering=Integration"}, c.altitude, c.pitch,
                   c.shafts, 10.0, 1);
    ASSERT_FALSE(pairs.empty());
    const double earthRadius = AtmosphereParameters{}.earthRadius;  // the defaults the run used
    const double horizon = -glm::degrees(std::acos(earthRadius / (earthRadius + c.altitude)));
    double brightest = 0.0, squaredError = 0.0, worst = 0.0, worstInBand = 0.0;
    int counted = 0;
    for (const auto& [captured, expected, viewDir] : pairs) {
        const double elevation = glm::degrees(std::asin(viewDir.y));
        const bool inBand = std::abs(elevation - horizon) < 0.125;
        const double bound = c.shafts && elevation < horizon && elevation > horizon - 0.25 ? kShaftsGroundNearHorizonWorst : 0.01;
        for (int ch = 0; ch < 3; ++ch) {
            const double error = std::abs(captured[ch] - expected[ch]) / expected[ch];
            if (inBand) {
                worstInBand = std::max(worstInBand, error);
                continue;
            }
            brightest = std::max(brightest, expected[ch]);
            squaredError += (captured[ch] - expected[ch]) * (captured[ch] - expected[ch]);
            ++counted;
            worst = std::max(worst, error);
            EXPECT_LT(error, bound) << "view " << elevation << " degrees up (horizon " << horizon << "), channel " << ch << ": " << captured[ch]
                                   << " vs " << expected[ch];
        }
    }
    ASSERT_GT(counted, 0);
    const double psnr = 10.0 * std::log10(brightest * brightest / std::max(squaredError / counted, 1e-30));
    std::printf("Grazing Integration%s from %.0f m, sun at %+.1f degrees, views %.2f to %.2f degrees: %d values, largest error %.4f, "
                "%.1f dB; within 0.125 degrees of the horizon (%.2f) largest %.4f\n",
                c.shafts ? " (light shafts)" : "", c.altitude, c.sunElevation, c.pitch - 5.0, c.pitch + 5.0, counted, worst, psnr, horizon,
                worstInBand);
    EXPECT_GT(psnr, 50.0);
}

// The shafts' cases are the full tier's (tests/CMakeLists.txt): about 10 s each; so is the low
// sun from 1 km (16 s; the quick tier keeps 1 km at 20 degrees and 40 km).
class GrazingIntegration : public ::testing::TestWithParam<GrazingCase> {};
class GrazingIntegrationLowSun : public ::testing::TestWithParam<GrazingCase> {};
class GrazingIntegrationWithShafts : public ::testing::TestWithParam<GrazingCase> {};

TEST_P(GrazingIntegration, ConvergesAtTheDefaultStepCount) { expectGrazingIntegrationConverges(GetParam()); }
TEST_P(GrazingIntegrationLowSun, ConvergesAtTheDefaultStepCount) { expectGrazingIntegrationConverges(GetParam()); }
TEST_P(GrazingIntegrationWithShafts, ConvergesAtTheDefaultStepCount) { expectGrazingIntegrationConverges(GetParam()); }

std::string grazingCaseName(const ::testing::TestParamInfo<GrazingCase>& param) {
    return std::to_string(static_cast<int>(param.param.altitude)) + "m_sun" + std::to_string(static_cast<int>(param.param.sunElevation));
}

INSTANTIATE_TEST_SUITE_P(AboveAndBelowTheHorizon, GrazingIntegration,
                         ::testing::Values(GrazingCase{1000.0, 20.0, -0.65}, GrazingCase{40000.0, 20.0, -6.2}), grazingCaseName);
INSTANTIATE_TEST_SUITE_P(AboveAndBelowTheHorizon, GrazingIntegrationLowSun, ::testing::Values(GrazingCase{1000.0, 5.0, -0.65}), grazingCaseName);
INSTANTIATE_TEST_SUITE_P(AboveAndBelowTheHorizon, GrazingIntegrationWithShafts,
                         ::testing::Values(GrazingCase{1000.0, 20.0, -0.65, true}, GrazingCase{1000.0, 5.0, -0.65, true},
                                           GrazingCase{40000.0, 20.0, -6.2, true}),
                         grazingCaseName);

}  // namespace
}  // namespace firmament::test
