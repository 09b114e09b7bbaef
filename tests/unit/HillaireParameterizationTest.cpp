// Hillaire 2020's table parameterizations on the CPU (src/atmosphere/hillaire/): each mapping's
// defining points, its round trip, and the crowding it is chosen for.
#include "atmosphere/hillaire/HillaireParameterization.h"

#include <gtest/gtest.h>

#include <cmath>

namespace firmament::atmosphere::hillaire {
namespace {

constexpr double kPi = 3.14159265358979323846;

// The zenith cosine of the horizon seen from radius r, by the right triangle of the centre, the
// point and the tangent point: -rho / r.
double horizonCosine(const AtmosphereParameters& p, double r) { return -std::sqrt(r * r - p.earthRadius * p.earthRadius) / r; }

TEST(HillaireParameterization, TablesHaveThePapersSizesAtFull) {
    const Dimensions d = Dimensions::of(LutResolution::Full);
    EXPECT_EQ(d.transmittanceMu, 256);
    EXPECT_EQ(d.transmittanceR, 64);
    EXPECT_EQ(d.multipleScatteringMuS, 32);
    EXPECT_EQ(d.multipleScatteringR, 32);
    EXPECT_EQ(d.skyViewLongitude, 192);
    EXPECT_EQ(d.skyViewLatitude, 108);
    EXPECT_EQ(d.aerialPerspective, 32);
    EXPECT_LT(Dimensions::of(LutResolution::Small).transmittanceMu, d.transmittanceMu);
}

TEST(HillaireParameterization, DistanceToTheTopMatchesTheGeometry) {
    const AtmosphereParameters p;
    EXPECT_NEAR(distanceToTop(p, p.earthRadius, 1.0), p.atmosphereHeight, 1e-6);
    EXPECT_NEAR(distanceToTop(p, p.earthRadius + 1000.0, 1.0), p.atmosphereHeight - 1000.0, 1e-6);
    // Along the horizon from the ground: the tangent to the ground meets the top after H.
    EXPECT_NEAR(distanceToTop(p, p.earthRadius, 0.0), std::sqrt(p.topRadius() * p.topRadius() - p.earthRadius * p.earthRadius), 1e-6);
    // Any ray: the exit point lies on the top sphere.
    for (const double mu : {-0.3, 0.1, 0.7}) {
        const double r = p.earthRadius + 20.0e3, d = distanceToTop(p, r, mu);
        const glm::dvec2 exit(d * std::sqrt(1.0 - mu * mu), r + d * mu);
        EXPECT_NEAR(glm::length(exit), p.topRadius(), 1e-6) << mu;
    }
}

TEST(HillaireParameterization, TransmittanceAxesEndAtTheGroundTheTopTheZenithAndTheHorizon) {
    const AtmosphereParameters p;
    EXPECT_NEAR(transmittanceUnit(p, p.earthRadius, 1.0).y, 0.0, 1e-12);
    EXPECT_NEAR(transmittanceUnit(p, p.topRadius(), 1.0).y, 1.0, 1e-12);
    for (const double altitude : {0.0, 1000.0, 30.0e3, 79.0e3}) {
        const double r = p.earthRadius + altitude;
        EXPECT_NEAR(transmittanceUnit(p, r, 1.0).x, 0.0, 1e-9) << altitude;
        EXPECT_NEAR(transmittanceUnit(p, r, horizonCosine(p, r)).x, 1.0, 1e-6) << altitude;
    }
    // Texels crowd near the ground: the first tenth of the axis covers less than a tenth of the
    // height (rho / H grows as the square root of the altitude near the ground).
    EXPECT_LT(transmittanceCoordinates(p, {0.5, 0.1}).r - p.earthRadius, 0.02 * p.atmosphereHeight);
}

TEST(HillaireParameterization, TransmittanceRoundTrips) {
    const AtmosphereParameters p;
    for (double y = 0.0; y <= 1.0; y += 0.125)
        for (double x = 0.0; x <= 1.0; x += 0.0625) {
            const RadiusAndCosine c = transmittanceCoordinates(p, {x, y});
            EXPECT_GE(c.mu, horizonCosine(p, c.r) - 1e-9) << x << "," << y;  // never below the horizon
            const glm::dvec2 back = transmittanceUnit(p, c.r, c.mu);
            EXPECT_NEAR(back.x, x, 1e-6) << x << "," << y;
            EXPECT_NEAR(back.y, y, 1e-9) << x << "," << y;
        }
    for (const double altitude : {10.0, 2000.0, 50.0e3})
        for (const double mu : {1.0, 0.5, 0.05, -0.02}) {
            const double r = p.earthRadius + altitude;
            if (mu < horizonCosine(p, r)) continue;
            const RadiusAndCosine c = transmittanceCoordinates(p, transmittanceUnit(p, r, mu));
            EXPECT_NEAR(c.r, r, 1e-5) << altitude << " " << mu;
            EXPECT_NEAR(c.mu, mu, 1e-7) << altitude << " " << mu;
        }
}

TEST(HillaireParameterization, MultipleScatteringIsLinearInTheSunCosineAndTheAltitude) {
    const AtmosphereParameters p;
    EXPECT_EQ(multipleScatteringUnit(p, p.earthRadius, -1.0), glm::dvec2(0.0, 0.0));
    EXPECT_EQ(multipleScatteringUnit(p, p.topRadius(), 1.0), glm::dvec2(1.0, 1.0));
    EXPECT_NEAR(multipleScatteringUnit(p, p.earthRadius + 0.5 * p.atmosphereHeight, 0.0).x, 0.5, 1e-12);
    EXPECT_NEAR(multipleScatteringUnit(p, p.earthRadius + 0.5 * p.atmosphereHeight, 0.0).y, 0.5, 1e-12);
    for (const double u : {0.0, 0.3, 1.0})
        for (const double v : {0.0, 0.7, 1.0}) {
            const RadiusAndCosine c = multipleScatteringCoordinates(p, {u, v});
            const glm::dvec2 back = multipleScatteringUnit(p, c.r, c.mu);
            EXPECT_NEAR(back.x, u, 1e-12);
            EXPECT_NEAR(back.y, v, 1e-12);
        }
}

TEST(HillaireParameterization, SkyViewPutsTheHorizonOnItsMiddleRowFromAnyAltitude) {
    const AtmosphereParameters p;
    for (const double altitude : {0.0, 1000.0, 10.0e3, 40.0e3, 400.0e3}) {
        const double r = p.earthRadius + altitude;
        EXPECT_NEAR(skyViewUnit(p, r, 1.0, 1.0).y, 0.0, 1e-9) << altitude;             // the zenith
        EXPECT_NEAR(skyViewUnit(p, r, -1.0, 1.0).y, 1.0, 1e-9) << altitude;            // the nadir
        EXPECT_NEAR(skyViewUnit(p, r, horizonCosine(p, r), 1.0).y, 0.5, 1e-6) << altitude;  // the true horizon
        EXPECT_NEAR(horizonZenithAngle(p, r), std::acos(horizonCosine(p, r)), 1e-9) << altitude;
    }
    EXPECT_NEAR(horizonZenithAngle(p, p.earthRadius), kPi / 2.0, 1e-12);
    EXPECT_NEAR(skyViewUnit(p, p.earthRadius, 0.3, 1.0).x, 0.0, 1e-12);   // toward the sun
    EXPECT_NEAR(skyViewUnit(p, p.earthRadius, 0.3, -1.0).x, 1.0, 1e-12);  // away from it
}

TEST(HillaireParameterization, SkyViewCrowdsItsRowsAboutTheHorizonAndRoundTrips) {
    const AtmosphereParameters p;
    const double r = p.earthRadius + 1000.0;
    // The angle a row spans: near the horizon a fraction of what it spans near the zenith.
    const auto zenithAngle = [&](double v) { return std::acos(skyViewDirection(p, r, {0.5, v}).mu); };
    const double nearHorizon = zenithAngle(0.5) - zenithAngle(0.49), nearZenith = zenithAngle(0.01) - zenithAngle(0.0);
    EXPECT_LT(nearHorizon, 0.1 * nearZenith);
    double previous = -1.0;
    for (double v = 0.0; v <= 1.0; v += 1.0 / 64.0) {
        const double theta = zenithAngle(v);
        EXPECT_GT(theta, previous) << v;  // from the zenith down to the nadir
        previous = theta;
        for (const double u : {0.0, 0.25, 0.8, 1.0}) {
            const SkyViewDirection d = skyViewDirection(p, r, {u, v});
            const glm::dvec2 back = skyViewUnit(p, r, d.mu, d.cosAzimuth);
            EXPECT_NEAR(back.x, u, 1e-7) << u << "," << v;
            EXPECT_NEAR(back.y, v, 1e-6) << u << "," << v;
        }
    }
}

TEST(HillaireParameterization, AerialPerspectiveSlicesAreLinearToThirtyTwoKilometres) {
    EXPECT_EQ(aerialPerspectiveUnit(0.0), 0.0);
    EXPECT_EQ(aerialPerspectiveUnit(16.0e3), 0.5);
    EXPECT_EQ(aerialPerspectiveUnit(32.0e3), 1.0);
    EXPECT_EQ(aerialPerspectiveUnit(100.0e3), 1.0);
    EXPECT_EQ(aerialPerspectiveDistance(0.25), 8.0e3);
    EXPECT_NEAR(unitToTexture(0.0, 32), 0.5 / 32.0, 1e-15);
    EXPECT_NEAR(textureToUnit(unitToTexture(0.37, 32), 32), 0.37, 1e-15);
}

}  // namespace
}  // namespace firmament::atmosphere::hillaire
