// The CPU reference of the tone mapping operators against the properties their papers give
// them (where black, middle and white go), monotonicity, safety for any input, and the
// frame-rate independence of light adaptation.
#include "postfx/ToneMappingCurves.h"

#include <gtest/gtest.h>

#include <cmath>
#include <limits>
#include <utility>
#include <vector>

namespace firmament::tonemap {
namespace {

constexpr ToneMapOperator kAllOperators[] = {ToneMapOperator::Exp,        ToneMapOperator::Reinhard,
                                             ToneMapOperator::ReinhardModified, ToneMapOperator::Uncharted2,
                                             ToneMapOperator::FilmicAlu,  ToneMapOperator::Logarithmic,
                                             ToneMapOperator::AdaptiveLogarithmic};

TEST(ToneMappingCurves, OperatorsPassThroughTheirDefiningPoints) {
    EXPECT_NEAR(exponential(std::log(2.0)), 0.5, 1e-12);
    EXPECT_NEAR(reinhard(1.0), 0.5, 1e-12);                       // Reinhard eq. 3: L / (1 + L)
    for (const double white : {0.5, 3.0, 8.0}) {
        EXPECT_NEAR(reinhardModified(white, white), 1.0, 1e-12);  // eq. 4 maps Lwhite to 1
        EXPECT_NEAR(logarithmic(white, white), 1.0, 1e-12);
        EXPECT_NEAR(adaptiveLogarithmic(white, white), 1.0, 1e-12);  // Drago eq. 4 with Ldmax = 100
        EXPECT_NEAR(uncharted2(white / kHableExposureBias, white), 1.0, 1e-6);
    }
    EXPECT_NEAR(reinhardModified(2.0, 1e9), reinhard(2.0), 1e-9);  // an infinite white point is plain Reinhard
    EXPECT_NEAR(hableCurve(0.0), 0.0, 1e-7);                        // the filmic curve starts at black
    EXPECT_EQ(filmicAlu(kFilmicAluOffset), 0.0);                    // ... so does the ALU curve, after its offset
    EXPECT_NEAR(filmicAlu(1e6), 1.0, 1e-5);                        // and approaches white
    EXPECT_NEAR(srgbEncode(0.5), 0.7353569830524495, 1e-12);
}

// Display values along a colour ramp from 1e-6 up to the half-float maximum the frame can hold
// (50 steps a decade) never decrease. (Beyond it the per-channel clamp changes the colour.)
TEST(ToneMappingCurves, EveryOperatorIsMonotonic) {
    for (const ToneMapOperator op : kAllOperators) {
        for (const double white : {0.01, 1.0, 3.0, 10.0}) {
            for (const double saturation : {0.01, 1.0, 2.0}) {
                const Parameters p{op, 1.0, white, saturation};
                glm::dvec3 previous(0.0);
                for (int i = 0; std::pow(10.0, -6.0 + i / 50.0) <= kMaxRadiance; ++i) {
                    const double L = std::pow(10.0, -6.0 + i / 50.0);
                    const glm::dvec3 d = toDisplay(glm::dvec3(L, 0.7 * L, 0.2 * L), p);
                    for (int c = 0; c < 3; ++c)
                        ASSERT_GE(d[c], previous[c] - 1e-12)
                            << kToneMapOperatorNames[static_cast<size_t>(op)] << " white " << white << " at L " << L;
                    previous = d;
                }
            }
        }
    }
}

TEST(ToneMappingCurves, NoNanForZeroNegativeHugeOrInfiniteInput) {
    const double inf = std::numeric_limits<double>::infinity();
    const glm::dvec3 inputs[] = {glm::dvec3(0.0), glm::dvec3(-1.0), glm::dvec3(-1e30, 5.0, 0.0), glm::dvec3(65504.0),
                                 glm::dvec3(1e30), glm::dvec3(inf, 1.0, 0.0), glm::dvec3(-inf)};
    for (const ToneMapOperator op : kAllOperators)
        for (const glm::dvec3& input : inputs)
            for (const double exposure : {1e-6, 1.0, 1e6}) {
                const glm::dvec3 d = toDisplay(input, Parameters{op, exposure, 0.01, 2.0});
                for (int c = 0; c < 3; ++c) {
                    ASSERT_TRUE(std::isfinite(d[c])) << kToneMapOperatorNames[static_cast<size_t>(op)];
                    ASSERT_GE(d[c], 0.0);
                    ASSERT_LE(d[c], 1.0);
                }
            }
}

// The luminance operators carry the colour over: with saturation 1 the output keeps the
// ratios of the linear channels.
TEST(ToneMappingCurves, LuminanceOperatorsKeepTheChromaticityAtSaturationOne) {
    const glm::dvec3 radiance(0.3, 0.2, 0.05);
    const Parameters p{ToneMapOperator::Reinhard, 1.0, 3.0, 1.0};
    const glm::dvec3 d = toDisplay(radiance, p);
    auto linear = [](double e) { return e <= 0.04045 ? e / 12.92 : std::pow((e + 0.055) / 1.055, 2.4); };
    const double Ld = reinhard(relativeLuminance(radiance));
    for (int c = 0; c < 3; ++c) EXPECT_NEAR(linear(d[c]), Ld * radiance[c] / relativeLuminance(radiance), 1e-9);
}

TEST(ToneMappingCurves, AutoExposureBringsTheAverageToMiddleGray) {
    EXPECT_NEAR(autoExposure(4.0, 0.18, 1.0) * 4.0, 0.18, 1e-15);
    EXPECT_NEAR(autoExposure(4.0, 0.18, 2.0) * 4.0, 0.36, 1e-15);  // +1 EV of compensation
    const std::vector<glm::dvec3> uniform(10, glm::dvec3(2.0));
    EXPECT_NEAR(meanLogLuminance(uniform), std::log(kLogLuminanceDelta + relativeLuminance(glm::dvec3(2.0))), 1e-12);
}

// Histogram metering: black texels are left out; what remains is averaged between the two
// percentiles, each bin by the mean of its values (so exactly, when each value has a bin of
// its own or a bin lies wholly inside the range).
TEST(ToneMappingCurves, HistogramMeteringAveragesBetweenPercentilesWithoutBlack) {
    const float black = static_cast<float>(std::log(kLogLuminanceDelta));
    EXPECT_NEAR(histogramMeanLogLuminance(std::vector<float>(64, black), 0.1, 0.98), std::log(kLogLuminanceDelta), 1e-6) << "all black";
    // 40 black texels and 60 at ln L = 1.5: the metered value is 1.5, whatever the percentiles.
    std::vector<float> halves(40, black);
    halves.insert(halves.end(), 60, 1.5f);
    for (const auto& [low, high] : {std::pair{0.1, 0.98}, std::pair{0.0, 1.0}, std::pair{0.45, 0.55}})
        EXPECT_NEAR(histogramMeanLogLuminance(halves, low, high), 1.5, 1e-6) << low << " to " << high;
    // Four groups of 25 values, one per bin, far apart: between the 25% and 75% percentiles only
    // the middle two count; from 10%, 15 of the first's 25 too.
    std::vector<float> groups;
    for (const float v : {-6.0f, -2.0f, 2.0f, 6.0f}) groups.insert(groups.end(), 25, v);
    EXPECT_NEAR(histogramMeanLogLuminance(groups, 0.25, 0.75), 0.0, 1e-6);
    EXPECT_NEAR(histogramMeanLogLuminance(groups, 0.10, 0.75), (15.0 * -6.0 + 25.0 * -2.0 + 25.0 * 2.0) / 65.0, 1e-6);
    // Values beyond the bins' range count at its ends.
    EXPECT_NEAR(histogramMeanLogLuminance(std::vector<float>(10, 50.0f), 0.0, 1.0), kHistogramHighestLog, 1e-6);
}

// Adaptation covers 1 - 1/e of the way in one time constant, and n frames of dt / n cover
// exactly what one frame of dt does: the frame rate does not change the path.
TEST(ToneMappingCurves, AdaptationDoesNotDependOnTheFrameRate) {
    const double tau = 0.5;
    EXPECT_NEAR(adaptationWeight(tau, tau), 1.0 - std::exp(-1.0), 1e-15);
    for (const int frames : {1, 7, 30, 144}) {
        double adapted = 0.0;  // in the log domain, towards 1
        for (int i = 0; i < frames; ++i) adapted += (1.0 - adapted) * adaptationWeight(1.0 / frames, tau);
        EXPECT_NEAR(adapted, 1.0 - std::exp(-1.0 / tau), 1e-12) << frames << " frames";
    }
    EXPECT_EQ(adaptationWeight(0.0, tau), 0.0);
    EXPECT_EQ(adaptationWeight(1.0, 0.0), 1.0);  // no time constant: jump
}

}  // namespace
}  // namespace firmament::tonemap
