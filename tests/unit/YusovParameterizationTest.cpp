// Yusov's parameterization (Yusov 2013, eq. 4-7) on the CPU: its defining values, round
// trips world -> unit -> world and unit -> world -> unit, and the horizon's two halves.
#include "atmosphere/yusov/YusovParameterization.h"

#include <gtest/gtest.h>

#include <cmath>
#include <random>

namespace firmament::atmosphere {
namespace {

const AtmosphereParameters kAtmosphere{};

TEST(YusovParameterization, DefiningValues) {
    const ScatteringCoordinates ground{0.0, 1.0, 1.0, 1.0};
    const UnitCoordinates u = toUnit(kAtmosphere, ground);
    EXPECT_EQ(u.altitude, 0.0);                                                              // eq. 4
    EXPECT_NEAR(toUnit(kAtmosphere, {80.0e3, 1.0, 1.0, 1.0}).altitude, 1.0, 1e-15);
    EXPECT_NEAR(toUnit(kAtmosphere, {20.0e3, 1.0, 1.0, 1.0}).altitude, 0.5, 1e-15);  // sqrt(1/4)
    EXPECT_NEAR(u.viewZenith, 1.0, 1e-15);                                                  // eq. 5: the zenith
    EXPECT_TRUE(u.aboveHorizon);
    EXPECT_NEAR(u.sunZenith, 1.0, 1e-12);                                                   // eq. 6: the sun at the zenith
    EXPECT_NEAR(u.sunView, 0.0, 1e-15);                                                     // eq. 7: theta = 0
    EXPECT_NEAR(toUnit(kAtmosphere, {0.0, 1.0, 1.0, -1.0}).sunView, 1.0, 1e-15);           // theta = pi
    EXPECT_NEAR(toUnit(kAtmosphere, {0.0, 1.0, 1.0, 0.0}).sunView, 0.5, 1e-15);            // theta = pi / 2
    // eq. 6 maps the lowest sun it distinguishes to (almost) 0 and clamps below it.
    EXPECT_NEAR(toUnit(kAtmosphere, {0.0, 1.0, -0.1975, 1.0}).sunZenith, 0.0, 1e-3);
    EXPECT_EQ(toUnit(kAtmosphere, {0.0, 1.0, -0.9, 1.0}).sunZenith, toUnit(kAtmosphere, {0.0, 1.0, -0.1975, 1.0}).sunZenith);
    // The horizon at 10 km: c_h = -sqrt(h (2R + h)) / (R + h), the tangent to the sphere.
    const double h = 10.0e3, R = kAtmosphere.earthRadius;
    EXPECT_NEAR(cosHorizon(kAtmosphere, h), -std::sqrt(1.0 - R * R / ((R + h) * (R + h))), 1e-15);
    // Looking straight down is the far end of the lower half.
    const UnitCoordinates down = toUnit(kAtmosphere, {h, -1.0, 1.0, -1.0});
    EXPECT_FALSE(down.aboveHorizon);
    EXPECT_NEAR(down.viewZenith, 1.0, 1e-15);
}

TEST(YusovParameterization, WorldToUnitToWorldRoundTrips) {
    std::mt19937 random(4);
    std::uniform_real_distribution<double> unit(0.0, 1.0);
    for (int i = 0; i < 10000; ++i) {
        ScatteringCoordinates c;
        c.altitude = unit(random) * kAtmosphere.atmosphereHeight;
        c.cosView = unit(random) * 2.0 - 1.0;
        c.cosSun = -0.1975 + unit(random) * 1.1975;
        c.cosSunView = unit(random) * 2.0 - 1.0;
        const ScatteringCoordinates back = fromUnit(kAtmosphere, toUnit(kAtmosphere, c));
        ASSERT_NEAR(back.altitude, c.altitude, 1e-9 * kAtmosphere.atmosphereHeight);
        ASSERT_NEAR(back.cosView, c.cosView, 1e-9) << "altitude " << c.altitude;
        ASSERT_NEAR(back.cosSun, c.cosSun, 1e-9);
        ASSERT_NEAR(back.cosSunView, c.cosSunView, 1e-7);  // acos near +-1 loses digits
    }
}

TEST(YusovParameterization, UnitToWorldToUnitRoundTrips) {
    std::mt19937 random(5);
    std::uniform_real_distribution<double> unit(0.0, 1.0);
    for (int i = 0; i < 10000; ++i) {
        UnitCoordinates u{unit(random), unit(random), i % 2 == 0, unit(random), unit(random)};
        u.sunZenith = std::max(u.sunZenith, 0.001);  // below this eq. 6 clamps
        // Below x = 0.01 the view cosine differs from the horizon's by t = x^5 < 1e-10, too
        // close to 1e-16 rounding to come back; the first texel off the horizon is at x = 1/63.
        u.viewZenith = std::max(u.viewZenith, 0.01);
        const UnitCoordinates back = toUnit(kAtmosphere, fromUnit(kAtmosphere, u), u.aboveHorizon);
        ASSERT_NEAR(back.altitude, u.altitude, 1e-12);
        ASSERT_NEAR(back.viewZenith, u.viewZenith, 1e-7);
        ASSERT_NEAR(back.sunZenith, u.sunZenith, 1e-9);
        ASSERT_NEAR(back.sunView, u.sunView, 1e-6);
    }
}

// A look-up told to stay in the half above the horizon never jumps into the lower half: a
// point just below its local horizon reads the horizon's texel (0), not the far end.
TEST(YusovParameterization, ForcedHalfStaysOnItsSideOfTheHorizon) {
    const double h = 5.0e3;
    const double ch = cosHorizon(kAtmosphere, h);
    const ScatteringCoordinates justBelow{h, ch - 1e-4, 0.5, 0.5};
    EXPECT_FALSE(toUnit(kAtmosphere, justBelow).aboveHorizon);
    const UnitCoordinates forced = toUnit(kAtmosphere, justBelow, true);
    EXPECT_TRUE(forced.aboveHorizon);
    EXPECT_EQ(forced.viewZenith, 0.0);
    // Either side of the horizon the unit coordinate starts at 0 and grows like t^0.2.
    const ScatteringCoordinates justAbove{h, ch + 1e-4, 0.5, 0.5};
    EXPECT_NEAR(toUnit(kAtmosphere, justAbove).viewZenith, std::pow(1e-4 / (1.0 - ch), 0.2), 1e-12);
    EXPECT_NEAR(toUnit(kAtmosphere, justBelow).viewZenith, std::pow(1e-4 / (ch + 1.0), 0.2), 1e-12);
}

TEST(YusovParameterization, TexelsSpanTheWholeDomain) {
    AtmosphereParameters p;
    p.lut = LutDimensions::of(LutResolution::Small);
    const ScatteringCoordinates first = texelToWorld(p, {0, 0, 0});
    EXPECT_EQ(first.altitude, 0.0);
    EXPECT_NEAR(first.cosView, cosHorizon(p, 0.0), 1e-15);  // the lower half starts at the horizon
    const ScatteringCoordinates last = texelToWorld(p, {p.lut.height - 1, p.lut.viewZenith - 1, p.lut.sunZenith * p.lut.sunView - 1});
    EXPECT_NEAR(last.altitude, p.atmosphereHeight, 1e-9);
    EXPECT_NEAR(last.cosView, 1.0, 1e-15);
    EXPECT_NEAR(last.cosSun, 1.0, 1e-12);
    // The sun-view angle is clamped to what the two zenith angles allow.
    const ScatteringCoordinates up = texelToWorld(p, {3, p.lut.viewZenith - 1, p.lut.sunZenith - 1});
    EXPECT_NEAR(up.cosSunView, 1.0, 1e-12);  // view and sun both at the zenith
}

}  // namespace
}  // namespace firmament::atmosphere
