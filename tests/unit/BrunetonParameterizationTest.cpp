// Bruneton and Neyret 2008's parameterization (src/atmosphere/bruneton/BrunetonParameterization)
// in double precision: every texel's world point maps back onto that texel's centre, the
// horizon is the seam between the halves of the view zenith axis, and the 2D tables' mappings
// invert.
#include "atmosphere/bruneton/BrunetonParameterization.h"

#include <gtest/gtest.h>

#include <cmath>

namespace firmament::atmosphere::bruneton {
namespace {

constexpr double kTolerance = 1e-9;

TEST(BrunetonParameterization, EveryTexelMapsBackToItsCentre) {
    const AtmosphereParameters p;
    for (const LutResolution resolution : {LutResolution::Small, LutResolution::Full}) {
        const Dimensions n = Dimensions::of(resolution);
        const glm::ivec3 size = n.packed3d();
        for (int z = 1; z < size.z - 1; ++z)  // the first and last layers sit 10 m and 1 m inside
            for (int y = 0; y < size.y; ++y)
                for (int x = 0; x < size.x; ++x) {
                    const Coordinates c = inscatterTexel(p, n, {x, y, z});
                    const bool groundHalf = y < n.mu / 2;
                    // The horizon's texels (the first and the last) hold the ray along it, of either half.
                    if (y != 0 && y != n.mu - 1) {
                        ASSERT_EQ(hitsGround(p, c.r, c.mu), groundHalf) << x << "," << y << "," << z;
                    }
                    const glm::dvec4 u = inscatterUnit(p, n, c, groundHalf);
                    ASSERT_NEAR(unitToTexture(u.x, n.r), (z + 0.5) / n.r, kTolerance) << "r at layer " << z;
                    // u_mu is a distance over its largest value, so the texels whose distance is
                    // below the smallest (straight down: r - Rg; the zenith: Rt - r) repeat that
                    // ray (the 2008 mapping's waste); every other texel's mu comes back to its centre.
                    const double rho = std::sqrt(c.r * c.r - p.earthRadius * p.earthRadius);
                    const double horizonH = std::sqrt(p.topRadius() * p.topRadius() - p.earthRadius * p.earthRadius);
                    const int half = n.mu / 2;
                    const bool clamped = groundHalf ? (half - 1.0 - y) / (half - 1.0) * rho <= c.r - p.earthRadius
                                                    : (y - half) / (half - 1.0) * (rho + horizonH) <= p.topRadius() - c.r;
                    if (!clamped) {
                        ASSERT_NEAR(u.y, (y + 0.5) / n.mu, 1e-6) << "mu at " << x << "," << y << "," << z;
                    }
                    ASSERT_NEAR(unitToTexture(u.z, n.muS), (x % n.muS + 0.5) / n.muS, 1e-9) << "mu_s at " << x;
                    const double sliceNu = -1.0 + 2.0 * (x / n.muS) / (n.nu - 1.0);
                    if (std::abs(c.nu - sliceNu) < 1e-12) {
                        ASSERT_NEAR(u.w * (n.nu - 1.0), x / n.muS, kTolerance) << "nu at " << x;
                    }
                }
    }
}

TEST(BrunetonParameterization, TheHorizonIsTheSeamBetweenTheHalves) {
    const AtmosphereParameters p;
    const Dimensions n = Dimensions::of(LutResolution::Full);
    for (const double altitude : {1.0, 100.0, 5000.0, 40000.0, 79000.0}) {
        const double r = p.earthRadius + altitude;
        const double horizon = -std::sqrt(1.0 - (p.earthRadius / r) * (p.earthRadius / r));
        const Coordinates below{r, horizon - 1e-12, 0.5, 0.0}, above{r, horizon + 1e-12, 0.5, 0.0};
        EXPECT_TRUE(hitsGround(p, r, below.mu));
        EXPECT_FALSE(hitsGround(p, r, above.mu));
        // Each half's horizon is its outermost texel centre: the ground half's first, the sky half's last.
        EXPECT_NEAR(inscatterUnit(p, n, below, true).y, 0.5 / n.mu, 1e-3) << altitude;
        EXPECT_NEAR(inscatterUnit(p, n, above, false).y, 1.0 - 0.5 / n.mu, 1e-3) << altitude;
        // Straight down and straight up are the halves' inner ends.
        EXPECT_NEAR(inscatterUnit(p, n, {r, -1.0, 0.5, 0.0}, true).y, 0.5 - 0.5 / n.mu - (altitude / std::sqrt(r * r - p.earthRadius * p.earthRadius)) * (0.5 - 1.0 / n.mu), 1e-9);
        EXPECT_LT(inscatterUnit(p, n, {r, 1.0, 0.5, 0.0}, false).y, 0.5 + 0.5 / n.mu + 0.1);
    }
}

TEST(BrunetonParameterization, SunZenithMappingCoversMinus02To1) {
    const AtmosphereParameters p;
    const Dimensions n = Dimensions::of(LutResolution::Full);
    EXPECT_NEAR(inscatterUnit(p, n, {p.earthRadius + 10.0, 0.5, 1.0, 0.0}, false).z, 1.0, kTolerance);
    EXPECT_NEAR(inscatterUnit(p, n, {p.earthRadius + 10.0, 0.5, -0.2, 0.0}, false).z, 0.0, kTolerance);
    EXPECT_EQ(inscatterUnit(p, n, {p.earthRadius + 10.0, 0.5, -0.9, 0.0}, false).z, 0.0);
    EXPECT_NEAR(inscatterTexel(p, n, {0, 70, 5}).muS, -0.2, 1e-9);
    EXPECT_NEAR(inscatterTexel(p, n, {n.muS - 1, 70, 5}).muS, 1.0, 1e-9);
}

TEST(BrunetonParameterization, TwoDimensionalTablesInvert) {
    const AtmosphereParameters p;
    for (double ur = 0.0; ur <= 1.0; ur += 0.125)
        for (double umu = 0.0; umu <= 1.0; umu += 0.0625) {
            const Coordinates t = transmittanceCoordinates(p, {umu, ur});
            const glm::dvec2 back = transmittanceUnit(p, t.r, t.mu);
            EXPECT_NEAR(back.x, umu, 1e-9);
            EXPECT_NEAR(back.y, ur, 1e-9);
            const Coordinates e = irradianceCoordinates(p, {umu, ur});
            const glm::dvec2 backE = irradianceUnit(p, e.r, e.muS);
            EXPECT_NEAR(backE.x, umu, 1e-9);
            EXPECT_NEAR(backE.y, ur, 1e-9);
        }
    // The transmittance table's zenith axis runs from -0.15 to 1, the irradiance table's from -0.2.
    EXPECT_NEAR(transmittanceCoordinates(p, {0.0, 0.0}).mu, -0.15, 1e-12);
    EXPECT_NEAR(transmittanceCoordinates(p, {1.0, 0.0}).mu, 1.0, 1e-12);
    EXPECT_NEAR(irradianceCoordinates(p, {0.0, 0.0}).muS, -0.2, 1e-12);
}

}  // namespace
}  // namespace firmament::atmosphere::bruneton
