// The CPU reference model against closed forms: vertical and horizontal optical depths, the
// optically thin limit of single scattering, the Earth's shadow, the quadrature itself.
#include "reference/ReferenceAtmosphere.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cstdio>
#include <random>

#include <cmath>

namespace firmament::atmosphere {
namespace {

double luminanceOf(glm::dvec3 rgb) { return 0.2126 * rgb.r + 0.7152 * rgb.g + 0.0722 * rgb.b; }

constexpr double kPi = 3.14159265358979323846;

TEST(ReferenceAtmosphere, GaussLegendreIsExactForPolynomialsOfDegree15) {
    EXPECT_NEAR(gaussLegendre([](double x) { return std::pow(x, 15); }, 0.0, 1.0, 1), 1.0 / 16.0, 1e-15);
    EXPECT_NEAR(gaussLegendre([](double x) { return std::exp(-x); }, 0.0, 10.0, 8), 1.0 - std::exp(-10.0), 1e-12);
}

// Straight up, the path is radial: the net density is H (exp(-h / H) - exp(-H_atm / H)).
TEST(ReferenceAtmosphere, VerticalNetDensityMatchesTheClosedForm) {
    const AtmosphereParameters p;
    const ReferenceAtmosphere reference(p);
    for (const double h : {0.0, 1500.0, 12000.0, 60000.0}) {
        const glm::dvec3 net = reference.netDensityToTop(h, 1.0);
        const double rayleigh = p.rayleighScaleHeight * (std::exp(-h / p.rayleighScaleHeight) - std::exp(-p.atmosphereHeight / p.rayleighScaleHeight));
        const double mie = p.mieScaleHeight * (std::exp(-h / p.mieScaleHeight) - std::exp(-p.atmosphereHeight / p.mieScaleHeight));
        EXPECT_NEAR(net.x, rayleigh, 1e-9 * rayleigh) << h;
        EXPECT_NEAR(net.y, mie, 1e-9 * mie) << h;
    }
}

// Along the horizon from the ground, the net density is Chapman's grazing integral,
// sqrt(pi R H / 2) to first order in H / R (a correction of about H / (8 R) follows).
TEST(ReferenceAtmosphere, HorizontalNetDensityMatchesChapmansGrazingIntegral) {
    const AtmosphereParameters p;
    const glm::dvec3 net = ReferenceAtmosphere(p).netDensityToTop(0.0, 0.0);
    const double mie = std::sqrt(kPi * p.earthRadius * p.mieScaleHeight / 2.0);
    const double rayleigh = std::sqrt(kPi * p.earthRadius * p.rayleighScaleHeight / 2.0);
    EXPECT_NEAR(net.y, mie, 2e-3 * mie);
    EXPECT_NEAR(net.x, rayleigh, 5e-3 * rayleigh);  // the top at 80 km cuts the tail (exp(-10))
}

// With vanishing coefficients nothing is attenuated: looking up from the ground with the sun
// at the zenith, L1 = sum over species of beta P(1) H (1 - exp(-H_atm / H)).
TEST(ReferenceAtmosphere, SingleScatteringHasTheOpticallyThinLimit) {
    AtmosphereParameters p;
    p.rayleighScattering *= 1e-6;
    p.mieScattering *= 1e-6;
    p.mieExtinction *= 1e-6;
    const ReferenceAtmosphere reference(p);
    const glm::dvec3 L = reference.singleScattering({0.0, 1.0, 1.0, 1.0});
    const double rayleighPath = p.rayleighScaleHeight * (1.0 - std::exp(-p.atmosphereHeight / p.rayleighScaleHeight));
    const double miePath = p.mieScaleHeight * (1.0 - std::exp(-p.atmosphereHeight / p.mieScaleHeight));
    for (int c = 0; c < 3; ++c) {
        const double expected = p.rayleighScattering[c] * rayleighPhase(1.0) * rayleighPath + p.mieScattering[c] * miePhase(1.0, p.mieAsymmetry) * miePath;
        EXPECT_NEAR(L[c], expected, 1e-6 * expected) << "channel " << c;
    }
}

// Looking up from the ground with the sun at the zenith, the light scattered at P has crossed
// the whole column once, T(C -> P) T_sun(P) = T(ground -> top) wherever P is, so
// L1 = T(ground -> top) sum over species of beta P(1) H (1 - exp(-H_atm / H)), with the air
// made 20 times as dense (blue's column transmittance under 1%). This holds the attenuation
// towards the camera, which singleScattering accumulates node by node along the ray, to the
// closed form: a node's depth counted twice, or a step left out, breaks it.
TEST(ReferenceAtmosphere, SingleScatteringUpTheSunsRayCrossesTheColumnOnce) {
    AtmosphereParameters p;
    p.rayleighScattering *= 20.0;
    p.mieScattering *= 20.0;
    p.mieExtinction *= 20.0;
    const ReferenceAtmosphere reference(p);
    const glm::dvec3 L = reference.singleScattering({0.0, 1.0, 1.0, 1.0});
    const double rayleighPath = p.rayleighScaleHeight * (1.0 - std::exp(-p.atmosphereHeight / p.rayleighScaleHeight));
    const double miePath = p.mieScaleHeight * (1.0 - std::exp(-p.atmosphereHeight / p.mieScaleHeight));
    const glm::dvec3 column = glm::exp(-(p.rayleighScattering * rayleighPath + p.mieExtinction * miePath));
    EXPECT_LT(column.b, 0.01);
    for (int c = 0; c < 3; ++c) {
        const double expected =
            column[c] * (p.rayleighScattering[c] * rayleighPhase(1.0) * rayleighPath + p.mieScattering[c] * miePhase(1.0, p.mieAsymmetry) * miePath);
        std::printf("channel %d: %.12e against %.12e\n", c, L[c], expected);
        EXPECT_NEAR(L[c], expected, 1e-9 * expected) << "channel " << c;
    }
}

TEST(ReferenceAtmosphere, PhaseFunctionsIntegrateToOneOverTheSphere) {
    for (const double g : {0.0, 0.5, 0.76, 0.9}) {
        const double mie = 2.0 * kPi * gaussLegendre([&](double mu) { return miePhase(mu, g); }, -1.0, 1.0, 256);
        EXPECT_NEAR(mie, 1.0, 1e-9) << "g " << g;  // Cornette-Shanks is normalised exactly
    }
    EXPECT_NEAR(2.0 * kPi * gaussLegendre(rayleighPhase, -1.0, 1.0, 1), 1.0, 1e-14);
}

// With the sun 30 degrees below the horizon, every point of the atmosphere above the camera
// (up to 80 km) is in the Earth's shadow, so no light is scattered.
TEST(ReferenceAtmosphere, TheEarthsShadowIsDark) {
    const ReferenceAtmosphere reference{AtmosphereParameters{}};
    const glm::dvec3 L = reference.singleScattering({0.0, 1.0, -0.5, -0.5});
    EXPECT_EQ(L, glm::dvec3(0.0));
    // At dusk (sun 2 degrees down) the zenith sky from the ground is lit high up, and dimmer
    // than with the sun 2 degrees up.
    const double dusk = reference.singleScattering({0.0, 1.0, std::sin(-2.0 * kPi / 180.0), 0.0}).b;
    const double sunset = reference.singleScattering({0.0, 1.0, std::sin(2.0 * kPi / 180.0), 0.0}).b;
    EXPECT_GT(dusk, 0.0);
    EXPECT_LT(dusk, sunset);
}

TEST(ReferenceAtmosphere, RaysEndAtTheGroundOrTheTop) {
    const AtmosphereParameters p;
    const ReferenceAtmosphere reference(p);
    const glm::dvec3 camera(0.0, p.earthRadius + 1000.0, 0.0);
    EXPECT_NEAR(reference.rayLength(camera, {0.0, -1.0, 0.0}), 1000.0, 1e-6);
    EXPECT_NEAR(reference.rayLength(camera, {0.0, 1.0, 0.0}), p.atmosphereHeight - 1000.0, 1e-6);
    EXPECT_TRUE(reference.inEarthShadow(camera, {0.0, -1.0, 0.0}));
    EXPECT_FALSE(reference.inEarthShadow(camera, {1.0, 0.0, 0.0}));
}

// The Monte Carlo reference's distances (sampleByDensity): along a grazing ray, 700 km long
// with its air in the first few kilometres, the mean of rho(s) / pdf(s) over 4000 draws is the
// density integral the quadrature gives, within 0.5%; and every draw's weight is close to that
// integral (the sampling follows the integrand), where uniform draws put 99% of the weight in
// 1% of the draws.
TEST(ReferenceAtmosphere, DistancesDrawnByDensityEstimateTheDensityIntegral) {
    const AtmosphereParameters p;
    const ReferenceAtmosphere reference(p);
    const glm::dvec3 start(0.0, p.earthRadius + 2.0, 0.0);
    const double elevation = 5.0 * kPi / 180.0;
    const glm::dvec3 dir(std::cos(elevation), std::sin(elevation), 0.0);
    const double length = reference.rayLength(start, dir);
    const glm::dvec3 exact = reference.netDensity(start, start + dir * length);
    std::mt19937 random(3);
    std::uniform_real_distribution<double> unit(0.0, 1.0);
    double sum = 0.0, largest = 0.0;
    constexpr int kDraws = 4000;
    for (int i = 0; i < kDraws; ++i) {
        double pdf = 0.0;
        const double s = reference.sampleByDensity(start, dir, length, unit(random), unit(random), pdf);
        ASSERT_GE(s, 0.0);
        ASSERT_LE(s, length);
        const glm::dvec3 rho = reference.density(glm::length(start + dir * s) - p.earthRadius);
        const double weight = (rho.x + rho.y) / pdf;
        sum += weight;
        largest = std::max(largest, weight);
    }
    EXPECT_NEAR(sum / kDraws, exact.x + exact.y, 0.005 * (exact.x + exact.y));
    EXPECT_LT(largest, 2.0 * (exact.x + exact.y));
}

// The Monte Carlo sky irradiance (skyIrradiance, single scattering only) against the same
// irradiance by quadrature: single scattering along 256 equal-area directions of the upper
// hemisphere, each weighted by its cosine. The sun 30 degrees up, on the ground. Within 4
// standard errors plus 1.5% (the quadrature's own error with 256 directions; measured 0.5-1.3%).
TEST(ReferenceAtmosphere, MonteCarloSkyIrradianceMatchesTheHemisphereIntegral) {
    const AtmosphereParameters p;
    const ReferenceAtmosphere reference(p);
    const glm::dvec3 ground(0.0, p.earthRadius + 1.0, 0.0);
    const double elevation = 30.0 * kPi / 180.0;
    const glm::dvec3 sunDir(std::cos(elevation), std::sin(elevation), 0.0);
    const glm::dvec3 quadrature = reference.singleScatteringIrradiance(ground, sunDir, 512);  // 256 directions up
    const auto estimate = reference.skyIrradiance(ground, sunDir, 1, 40000, 5u);
    for (int ch = 0; ch < 3; ++ch) {
        std::printf("channel %d: Monte Carlo %.5f +- %.5f, quadrature %.5f\n", ch, estimate.mean[ch], estimate.standardError[ch], quadrature[ch]);
        EXPECT_NEAR(estimate.mean[ch], quadrature[ch], 4.0 * estimate.standardError[ch] + 0.015 * quadrature[ch])
            << "channel " << ch << ": +- " << estimate.standardError[ch];
    }
}

// The paths' first order (next-event estimation at their first vertex) against single scattering
// by quadrature, from the ground toward the horizon with the sun high and low: within 4 standard
// errors. The path tracer the scores rest on (docs/atmosphere.md, "Scores") held to the closed
// quadrature where both compute the same light.
TEST(ReferenceAtmosphere, PathTracedFirstOrderMatchesTheQuadrature) {
    const AtmosphereParameters p;
    const ReferenceAtmosphere reference(p);
    const glm::dvec3 ground(0.0, p.earthRadius + 2.0, 0.0), view = glm::normalize(glm::dvec3(1.0, 0.1, 0.3));
    for (const double degrees : {45.0, 3.0}) {
        const double e = degrees * kPi / 180.0;
        const glm::dvec3 sun(std::cos(e) * 0.6, std::sin(e), std::cos(e) * 0.8);
        const auto traced = reference.scatteringOrders(ground, view, sun, 1, 1, 3000, 17u);
        const glm::dvec3 exact = reference.singleScattering(ground, view, sun);
        for (int ch = 0; ch < 3; ++ch)
            EXPECT_NEAR(traced.mean[ch], exact[ch], 4.0 * traced.standardError[ch]) << "sun " << degrees << " channel " << ch;
    }
}

// The scores' reference stops at the 16th order: the orders past it, traced up to the 40th, add
// under 1e-6 to the light of orders 1 to 16, from the ground toward the horizon at noon and in
// twilight (the sun 8 degrees down, where every photon has scattered more than once). Measured
// up to 4e-10 and 6e-11: the air is optically thin (a vertical optical depth of 0.1 to 0.4), so each
// order is a small fraction of the one before.
TEST(ReferenceAtmosphere, TheOrdersPastTheSixteenthAddNothingVisible) {
    const AtmosphereParameters p;
    const ReferenceAtmosphere reference(p);
    const glm::dvec3 ground(0.0, p.earthRadius + 2.0, 0.0), view = glm::normalize(glm::dvec3(1.0, 0.05, 0.0));
    for (const double degrees : {60.0, -8.0}) {
        const double e = degrees * kPi / 180.0;
        const glm::dvec3 sun(std::cos(e), std::sin(e), 0.0);
        const auto upTo16 = reference.scatteringOrders(ground, view, sun, 1, 16, 300, 23u);
        const auto past16 = reference.scatteringOrders(ground, view, sun, 17, 40, 300, 29u);
        const double share = luminanceOf(past16.mean) / luminanceOf(upTo16.mean);
        std::printf("sun %+.0f degrees: orders 17 to 40 add %.2e of orders 1 to 16\n", degrees, share);
        EXPECT_LT(share, 1e-6) << "sun " << degrees;
    }
}

// The path-traced orders converge as Monte Carlo should: with four times the paths the standard
// error falls (ideally to a half; between 0.1 and 0.8 of the first's, since the estimate of the
// error is itself noisy when a few paths carry much of the light: measured 0.37 to 0.39 with
// MinGW's standard library, 0.16 to 0.26 with the portable build's, whose uniform distribution
// draws other numbers from the same generator), and the two estimates agree within 4 combined
// standard errors. From 10 km looking down, the sun 20 degrees up.
TEST(ReferenceAtmosphere, PathTracedOrdersConverge) {
    const AtmosphereParameters p;
    const ReferenceAtmosphere reference(p);
    const glm::dvec3 start(0.0, p.earthRadius + 10000.0, 0.0), view = glm::normalize(glm::dvec3(1.0, -0.3, 0.2));
    const glm::dvec3 sun = glm::normalize(glm::dvec3(0.3, 0.36, 0.9));
    const auto few = reference.highOrderScattering(start, view, sun, 16, 400, 31u);
    const auto many = reference.highOrderScattering(start, view, sun, 16, 1600, 37u);
    for (int ch = 0; ch < 3; ++ch) {
        const double ratio = many.standardError[ch] / few.standardError[ch];
        EXPECT_GT(ratio, 0.1) << "channel " << ch;
        EXPECT_LT(ratio, 0.8) << "channel " << ch;
        const double combined = std::sqrt(few.standardError[ch] * few.standardError[ch] + many.standardError[ch] * many.standardError[ch]);
        EXPECT_NEAR(few.mean[ch], many.mean[ch], 4.0 * combined) << "channel " << ch;
    }
}

// Paths drawn toward the sunlit air (PathSampling::TowardSunlight) estimate the light paths drawn
// by density alone do, where the latter converge: orders 2 to 16 from the ground toward the
// horizon and from 10 km looking down, the sun 20 and 3 degrees up, within 4 combined standard
// errors.
TEST(ReferenceAtmosphere, PathsTowardSunlightAgreeWithPathsByDensityByDay) {
    const AtmosphereParameters p;
    const ReferenceAtmosphere reference(p);
    const glm::dvec3 starts[] = {glm::dvec3(0.0, p.earthRadius + 2.0, 0.0), glm::dvec3(0.0, p.earthRadius + 10000.0, 0.0)};
    const glm::dvec3 views[] = {glm::normalize(glm::dvec3(1.0, 0.1, 0.3)), glm::normalize(glm::dvec3(1.0, -0.3, 0.2))};
    for (int v = 0; v < 2; ++v)
        for (const double degrees : {20.0, 3.0}) {
            const double e = degrees * kPi / 180.0;
            const glm::dvec3 sun(std::cos(e) * 0.6, std::sin(e), std::cos(e) * 0.8);
            const auto byDensity = reference.highOrderScattering(starts[v], views[v], sun, 16, 800, 41u);
            const auto towardSunlight = reference.highOrderScattering(starts[v], views[v], sun, 16, 800, 43u, ReferenceAtmosphere::PathSampling::TowardSunlight);
            for (int ch = 0; ch < 3; ++ch) {
                const double combined = std::hypot(byDensity.standardError[ch], towardSunlight.standardError[ch]);
                std::printf("view %d, sun %+.0f, channel %d: by density %.4e +- %.1e, toward sunlight %.4e +- %.1e\n", v, degrees, ch,
                            byDensity.mean[ch], byDensity.standardError[ch], towardSunlight.mean[ch], towardSunlight.standardError[ch]);
                EXPECT_NEAR(towardSunlight.mean[ch], byDensity.mean[ch], 4.0 * combined) << "view " << v << " sun " << degrees << " channel " << ch;
            }
        }
}

// In deep twilight the paths drawn toward the sunlit air converge where those drawn by density
// do not: the zenith from the ground with the sun 12 and 18 degrees down, orders 2 to 16. By
// density, 16,000 paths give a few or none that reach the sunlit air (relative standard errors of
// the luminance of 0.96 and 1); toward sunlight, the same number give an estimate within
// kTwilightError (measured 14% and 29%), at least three times tighter, which 4,000 other paths
// confirm within 4 combined standard errors. The error is still heavy-tailed at -18 degrees: paths
// that reach the sunlit air differ by orders of magnitude in the transmittance of their way there.
TEST(ReferenceAtmosphere, PathsTowardSunlightConvergeInDeepTwilight) {
    constexpr double kTwilightError = 0.4;
    const AtmosphereParameters p;
    const ReferenceAtmosphere reference(p);
    const glm::dvec3 ground(0.0, p.earthRadius + 2.0, 0.0), zenith(0.0, 1.0, 0.0);
    const auto relativeError = [](const ReferenceAtmosphere::Estimate& e) {
        return luminanceOf(e.mean) > 0.0 ? luminanceOf(e.standardError) / luminanceOf(e.mean) : 1.0;
    };
    for (const double degrees : {-12.0, -18.0}) {
        const double e = degrees * kPi / 180.0;
        const glm::dvec3 sun(std::cos(e), std::sin(e), 0.0);
        constexpr auto toward = ReferenceAtmosphere::PathSampling::TowardSunlight;
        const auto byDensity = reference.highOrderScattering(ground, zenith, sun, 16, 16000, 47u);
        const auto few = reference.highOrderScattering(ground, zenith, sun, 16, 4000, 53u, toward);
        const auto many = reference.highOrderScattering(ground, zenith, sun, 16, 16000, 59u, toward);
        std::printf("sun %+.0f: by density %.3e (error %.2f); toward sunlight %.3e (error %.3f), 4,000 other paths %.3e (error %.3f)\n",
                    degrees, luminanceOf(byDensity.mean), relativeError(byDensity), luminanceOf(many.mean), relativeError(many),
                    luminanceOf(few.mean), relativeError(few));
        EXPECT_GT(relativeError(byDensity), 3.0 * relativeError(many)) << "sun " << degrees;
        EXPECT_LT(relativeError(many), kTwilightError) << "sun " << degrees;
        EXPECT_NEAR(luminanceOf(few.mean), luminanceOf(many.mean), 4.0 * std::hypot(luminanceOf(few.standardError), luminanceOf(many.standardError)))
            << "sun " << degrees;
    }
}

}  // namespace
}  // namespace firmament::atmosphere
