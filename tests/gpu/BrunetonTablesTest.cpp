// Bruneton and Neyret 2008's tables on the WARP device (src/atmosphere/bruneton): against the
// CPU reference (src/reference/ReferenceAtmosphere), and against Yusov's tables where the two
// models must agree: single scattering, multiple scattering over a black ground, and the
// sky's irradiance on the ground. Then the ground's bounce, which only Bruneton's model has.
#include "AtmosphereQueries.h"
#include "TableFilesCheck.h"
#include "WarpDevice.h"
#include "YusovTables.h"
#include "atmosphere/bruneton/BrunetonPrecomputation.h"
#include "atmosphere/bruneton/BrunetonTableFiles.h"
#include "atmosphere/yusov/YusovPrecomputation.h"
#include "gpu/CommonStates.h"
#include "gpu/ConstantBuffer.h"
#include "reference/ReferenceAtmosphere.h"
#include "tables/SphereDirections.h"

#include <Imath/half.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <cstring>
#include <random>
#include <string>
#include <utility>

namespace firmament::test {
namespace {

using atmosphere::ReferenceAtmosphere;

constexpr double kPi = 3.14159265358979323846;
constexpr double kRadianceFloor = 5e-4;  // per unit sun irradiance: about 2% of the noon zenith sky

// Bounds, each with what was measured here (see docs/atmosphere.md).
constexpr double kTransmittanceBound = 0.005;                                       // absolute; measured 2.2e-3
constexpr double kSingleBound = 0.35, kSingleMedianBound = 0.01, kSingleNinetiethBound = 0.05;  // measured 0.29, 0.0027, 0.027
constexpr double kSubnormalShareBound = 0.06;  // measured 1.7%, 16% unscaled
// The agreement with Yusov's tables: 0.011, 0.071 and 0.051, 0.18 while his stored the phases applied.
constexpr double kAgreeMedianBound = 0.01, kAgreeNinetiethBound = 0.06;              // measured 0.0030, 0.037
constexpr double kAgreeMultipleMedianBound = 0.04, kAgreeMultipleNinetiethBound = 0.18;  // measured 0.016, 0.13
constexpr double kHemisphereBound = 0.03;                                            // measured 0.8-2.3%
constexpr double kIrradianceBound = 0.065;  // measured 3.3% with the sun up to 48 degrees, 5.6% at the zenith
constexpr double kHighOrderBound = 0.30;                                             // measured 3-23%
constexpr double kAureoleRedBound = 0.02, kAureoleRebuiltBound = 0.40, kAureoleYusovBound = 0.02;  // measured 0.1%, 33%, 0.4%
constexpr std::pair<double, double> kZenithAt40Km{0.12, 0.25};                      // measured +18%
constexpr double kBounceBound = 0.15;                                                // measured 0-14%

class BrunetonModel : public WarpDevice {
protected:
    std::unique_ptr<BrunetonPrecomputation> bruneton(LutResolution resolution, int orders, double albedo) {
        BrunetonParameters p;
        p.physics.scatteringOrders = orders;
        p.physics.lut = LutDimensions::of(resolution);
        p.lut = atmosphere::bruneton::Dimensions::of(resolution);
        p.groundAlbedo = albedo;
        auto tables = std::make_unique<BrunetonPrecomputation>(device(), p);
        tables->runAll(context(), *productShaderLibrary);
        return tables;
    }

    std::unique_ptr<YusovPrecomputation> yusov(LutResolution resolution, int orders) {
        return computeYusovTables(device(), context(), *productShaderLibrary, resolution, orders);
    }

    // bruneton_probe.hlsl's `entry` (inscatter, transmittance, irradiance) at the queries.
    std::vector<glm::vec4> probe(const BrunetonPrecomputation& tables, const std::vector<Query>& queries, const char* entry) {
        ConstantBuffer<gpu::AtmosphereConstants> atmosphere(device());
        atmosphere.update(context(), tables.parameters().physics.constants());
        ConstantBuffer<gpu::BrunetonConstants> constants(device());
        constants.update(context(), tables.parameters().constants());
        const auto sampler = states::linearClamp(device());
        const firmament::BrunetonTables& t = tables.tables();
        return runProbe({"atmosphere/bruneton_probe.hlsl", entry, "cs_5_0", {}}, queries, {atmosphere.get(), constants.get()},
                        {t.transmittance.srv.Get(), t.irradiance.srv.Get(), t.inscatter.srv.Get()}, sampler.Get());
    }

    // Bruneton's in-scatter look-ups against one of Yusov's 4D tables at 240 random points away
    // from the horizon band: the errors relative to the brighter channel of Yusov's.
    Percentiles agreement(const BrunetonPrecomputation& b, const YusovPrecomputation& y, const Texture3D& yusovTable, unsigned seed) {
        const auto [queries, coordinates] = randomSkyQueries(b.parameters().physics, 240, seed, 2.0);
        const auto fromBruneton = probe(b, queries, "inscatter");
        const auto fromYusov = probeYusov(y, yusovTable, queries);
        std::vector<double> errors;
        for (size_t i = 0; i < queries.size(); ++i)
            errors.push_back(errorRelativeToBrightest(glm::dvec3(fromBruneton[i]), glm::dvec3(fromYusov[i]), kRadianceFloor));
        return percentiles(errors);
    }

    // lookup_probe.hlsl's scattering look-up into one of Yusov's 4D tables.
    std::vector<glm::vec4> probeYusov(const YusovPrecomputation& tables, const Texture3D& table, const std::vector<Query>& queries) {
        ConstantBuffer<gpu::AtmosphereConstants> atmosphere(device());
        atmosphere.update(context(), tables.parameters().constants());
        const auto sampler = states::linearClamp(device());
        return runProbe({"atmosphere/lookup_probe.hlsl", "scattering", "cs_5_0", {}}, queries, {atmosphere.get()},
                        {tables.tables().netDensity.srv.Get(), table.srv.Get()}, sampler.Get());
    }

    void checkInscatterAtRandomPoints(int points);
};

// The sun's transmittance from the transmittance table against the reference's direct
// integral, at random altitudes and sun elevations, the horizon included (an exact test).
// Bound: kTransmittanceBound.
TEST_F(BrunetonModel, TransmittanceMatchesTheCpu) {
    const auto tables = bruneton(LutResolution::Full, 1, 0.0);
    const AtmosphereParameters& p = tables->parameters().physics;
    const ReferenceAtmosphere reference(p);
    const std::vector<Query> queries = randomSunQueries(p, 256, 20);
    const double worst = sunTransmittanceError(reference, queries, probe(*tables, queries, "transmittance"), kTransmittanceBound);
    std::printf("Bruneton sun transmittance: largest absolute error %.2e\n", worst);
}

// Single scattering (one order) looked up at random points of full-size tables, against the
// reference's integral: the integration, Mie's colour rebuilt from its red channel, and the
// interpolation together. Views within 2 degrees of the horizon are left out, as for Yusov's
// tables (AtmosphereLutTest): the radiance changes there faster than the texels resolve.
// Errors relative to the brightest channel or kRadianceFloor.
TEST_F(BrunetonModel, SingleScatteringMatchesTheCpu) {
    const auto tables = bruneton(LutResolution::Full, 1, 0.0);
    const AtmosphereParameters& p = tables->parameters().physics;
    const ReferenceAtmosphere reference(p);
    const auto [queries, coordinates] = randomSkyQueries(p, 240, 21, 2.0);
    const auto got = probe(*tables, queries, "inscatter");
    std::vector<double> errors;
    for (size_t i = 0; i < queries.size(); ++i) {
        const glm::dvec3 expected = reference.singleScattering(coordinates[i]);
        errors.push_back(errorRelativeToBrightest(glm::dvec3(got[i]), expected, kRadianceFloor));
        EXPECT_LT(errors.back(), kSingleBound) << "query " << i << " (h " << coordinates[i].altitude << ", view " << coordinates[i].cosView
                                             << ", sun " << coordinates[i].cosSun << ", sun-view " << coordinates[i].cosSunView << "): " << got[i].r
                                             << "," << got[i].g << "," << got[i].b << " vs " << expected.r << "," << expected.g << "," << expected.b;
    }
    const Percentiles e = percentiles(errors);
    std::printf("Bruneton single scattering: median %.4f, 90th percentile %.4f, largest %.4f\n", e.median, e.ninetieth, e.largest);
    EXPECT_LT(e.median, kSingleMedianBound);
    EXPECT_LT(e.ninetieth, kSingleNinetiethBound);
}

// Twilight below the table's lowest sun (the sun axis ends 11.5 degrees down), as
// AtmosphereTables.TwilightFadesBelowTheTablesLowestSun holds Yusov's tables: the zenith's light
// from the ground (Small tables, orders 1 to 4, a black ground), the sun from 8 to 20 degrees
// down, falls at every degree, by a factor of 1.5 or more past the axis's end (measured 2.0 a
// degree), so that at 18 degrees down it is under 2% of that at 12 (measured 1.3%; the
// path-traced reference's, 0.6%). lookup.hlsli's fadeBelowTable carries the fall on past the end;
// without it every lower sun read the end's light, and the test failed so.
TEST_F(BrunetonModel, TwilightFadesBelowTheTablesLowestSun) {
    const auto tables = bruneton(LutResolution::Small, 4, 0.0);
    const AtmosphereParameters& p = tables->parameters().physics;
    const auto got = probe(*tables, twilightZenithQueries(p), "inscatter");
    expectTwilightFalls(got);
}

// The in-scatter table's half floats keep their precision from deep twilight to the brightest
// settings. With the default constants (Small tables, orders 1 to 4), under kSubnormalShareBound
// of the texels that hold any light are subnormal numbers (measured 1.7%; 16% with the table
// unscaled, which failed the test: the twilight sky's texels kept a few bits or none). With the
// settings' haziest air (aerosol density 5, no absorption), a white ground and 10 orders, the
// largest texel stays under a quarter of half's largest number, 65504 (measured 6.7e3: the light,
// 6.7 per unit sun irradiance at these sizes, times kBrunetonInscatterScale).
TEST_F(BrunetonModel, InscatterTableKeepsHalfsPrecision) {
    struct Census {
        size_t nonzero = 0, subnormal = 0;
        double largest = 0.0;
    };
    const auto census = [&](const BrunetonPrecomputation& tables) {
        const ReadbackVolume volume = readTexture3D(device(), context(), tables.tables().inscatter.texture.Get());
        Census c;
        for (size_t i = 0; i < volume.bytes.size() / 2; ++i) {
            std::uint16_t bits;
            std::memcpy(&bits, volume.bytes.data() + i * 2, 2);
            if ((bits & 0x7fff) == 0) continue;
            Imath::half h;
            h.setBits(bits);
            ++c.nonzero;
            if (h.isDenormalized()) ++c.subnormal;
            c.largest = std::max(c.largest, std::abs(static_cast<double>(static_cast<float>(h))));
        }
        return c;
    };
    const Census standard = census(*bruneton(LutResolution::Small, 4, 0.0));
    const double share = static_cast<double>(standard.subnormal) / static_cast<double>(standard.nonzero);
    std::printf("default constants: %zu texels hold light, %.1f%% of them subnormal; largest %.3e\n", standard.nonzero, 100.0 * share,
                standard.largest);
    EXPECT_LT(share, kSubnormalShareBound);

    BrunetonParameters hazy;
    hazy.physics.scatteringOrders = 10;
    hazy.physics.lut = LutDimensions::of(LutResolution::Small);
    hazy.lut = atmosphere::bruneton::Dimensions::of(LutResolution::Small);
    hazy.physics.mieScattering *= 5.0;
    hazy.physics.mieExtinction = hazy.physics.mieScattering;
    hazy.groundAlbedo = 1.0;
    BrunetonPrecomputation brightest(device(), hazy);
    brightest.runAll(context(), *productShaderLibrary);
    const Census bright = census(brightest);
    std::printf("haziest air, white ground, 10 orders: largest texel %.3e\n", bright.largest);
    EXPECT_TRUE(std::isfinite(bright.largest));
    EXPECT_LT(bright.largest, 65504.0 / 4.0);
}

// The two models from the same constants agree on single scattering (full-size tables, one
// order each), at random points away from the horizon band. Each model's own error against
// the reference is tested above and in AtmosphereLutTest; this checks that they
// describe one atmosphere.
TEST_F(BrunetonModel, ModelsAgreeOnSingleScattering) {
    const auto b = bruneton(LutResolution::Full, 1, 0.0);
    const auto y = yusov(LutResolution::Full, 1);
    const Percentiles e = agreement(*b, *y, y->tables().singleScattering, 22);
    std::printf("single scattering, Bruneton vs Yusov: median %.4f, 90th percentile %.4f, largest %.4f\n", e.median, e.ninetieth, e.largest);
    EXPECT_LT(e.median, kAgreeMedianBound);
    EXPECT_LT(e.ninetieth, kAgreeNinetiethBound);
}

// With a black ground both models compute the same multiple scattering (orders 1 to 4), by
// different parameterizations and integration orders: Yusov's multiple scattering table
// against Bruneton's in-scatter table, medium size.
TEST_F(BrunetonModel, ModelsAgreeOnMultipleScatteringOverABlackGround) {
    const auto b = bruneton(LutResolution::Medium, 4, 0.0);
    const auto y = yusov(LutResolution::Medium, 4);
    const Percentiles e = agreement(*b, *y, y->tables().multipleScattering, 23);
    std::printf("multiple scattering, Bruneton vs Yusov: median %.4f, 90th percentile %.4f, largest %.4f\n", e.median, e.ninetieth, e.largest);
    EXPECT_LT(e.median, kAgreeMultipleMedianBound);
    EXPECT_LT(e.ninetieth, kAgreeMultipleNinetiethBound);
}

// The sky's irradiance on the ground: Bruneton's E sums the sky light of orders 1 to N - 1
// (order N's light feeds no further order), Yusov's ambient light table integrates his
// multiple scattering table, orders 1 to N. So Bruneton with 4 orders (black ground) is
// compared with Yusov with 3, at Yusov's texels of sun elevation 0 to 90 degrees. Each is held
// to the reference on its own (AtmosphereLutTest's ambient light tests, and the two after this
// one); this checks that they light the ground alike. Suns above 48 degrees were left out while
// Yusov's tables stored the light with the phases applied: his ambient light was up to 15% off
// there. Now the two differ most with the sun at the zenith, by 5.6%.
TEST_F(BrunetonModel, SkyIrradianceAgreesWithYusovsAmbientLight) {
    const auto b = bruneton(LutResolution::Medium, 4, 0.0);
    const auto y = yusov(LutResolution::Medium, 3);
    const AtmosphereParameters& p = y->parameters();
    const ReadbackImage ambient = readTexture2D(device(), context(), y->tables().ambientLight.texture.Get());
    const int n = p.lut.ambientLight;
    std::vector<Query> queries;
    std::vector<int> texels;
    for (int texel = n / 2 + 4; texel < n; texel = texel + n / 16 < n ? texel + n / 16 : (texel == n - 1 ? n : n - 1)) {
        const double cosSun = texel / (n - 1.0) * 2.0 - 1.0;
        queries.push_back({glm::vec4(0.0f, static_cast<float>(p.earthRadius + 1.0), 0.0f, 0.0f), glm::vec4(0.0f),
                           glm::vec4(static_cast<float>(std::sqrt(1.0 - cosSun * cosSun)), static_cast<float>(cosSun), 0.0f, 0.0f)});
        texels.push_back(texel);
    }
    const auto got = probe(*b, queries, "irradiance");
    for (size_t i = 0; i < queries.size(); ++i) {
        std::uint16_t bits[4];
        std::memcpy(bits, ambient.bytes.data() + static_cast<size_t>(texels[i]) * 8, sizeof(bits));
        for (int ch = 0; ch < 3; ++ch) {
            Imath::half yusovValue;
            yusovValue.setBits(bits[ch]);
            const double expected = static_cast<float>(yusovValue);
            std::printf("sun cosine %.3f channel %d: Bruneton %.4e, Yusov %.4e\n", queries[i].sunDir.y, ch, got[i][ch], expected);
            EXPECT_NEAR(got[i][ch], expected, kIrradianceBound * expected + 1e-4) << "sun cosine " << queries[i].sunDir.y << " channel " << ch;
        }
    }
}

// The sky irradiance table E (orders 1 to 3 with 4 orders computed, black ground, medium
// tables) at 200 random altitudes and sun angles against the reference's Monte Carlo estimate
// (500 paths each): the error beyond 4 standard errors relative to the brightest channel or
// 1e-3. Measured: median 0, 90th percentile 4.1%, largest 11% (at 25-31 km, between the
// irradiance table's 16 radius rows, 5.3 km apart at medium size).
TEST_F(BrunetonModel, IrradianceAtRandomPointsMatchesMonteCarlo) {
    constexpr double kMedian = 0.02, kNinetieth = 0.08, kLargest = 0.16;
    const auto tables = bruneton(LutResolution::Medium, 4, 0.0);
    const AtmosphereParameters& p = tables->parameters().physics;
    const ReferenceAtmosphere reference(p);
    const std::vector<Query> queries = randomIrradianceQueries(p, 200, 34, p.atmosphereHeight);
    std::vector<glm::dvec3> table;
    for (const glm::vec4& g : probe(*tables, queries, "irradiance")) table.emplace_back(g);
    expectPercentilesBelow(irradianceErrors(reference, queries, table, 3, 500, 1e-3), "Bruneton's irradiance against Monte Carlo at 200 points",
                           kMedian, kNinetieth, kLargest);
}

// The sky's irradiance from tables of orders 1 and 2: E then holds order 1's light alone, which
// the reference integrates directly, single scattering over the upper hemisphere (512 of 1024
// equal-area directions), on the ground, for suns from the horizon to the zenith.
TEST_F(BrunetonModel, SkyIrradianceMatchesTheHemisphereIntegral) {
    const auto tables = bruneton(LutResolution::Full, 2, 0.0);
    const AtmosphereParameters& p = tables->parameters().physics;
    const ReferenceAtmosphere reference(p);
    std::vector<Query> queries;
    for (const double cosSun : {0.05, 0.2, 0.5, 0.8, 1.0})
        queries.push_back({glm::vec4(0.0f, static_cast<float>(p.earthRadius), 0.0f, 0.0f), glm::vec4(0.0f),
                           glm::vec4(static_cast<float>(std::sqrt(1.0 - cosSun * cosSun)), static_cast<float>(cosSun), 0.0f, 0.0f)});
    const auto got = probe(*tables, queries, "irradiance");
    for (size_t i = 0; i < queries.size(); ++i) {
        const glm::dvec3 sunDir(queries[i].sunDir);
        const glm::dvec3 expected = reference.singleScatteringIrradiance(glm::dvec3(0.0, p.earthRadius + 1.0, 0.0), sunDir, 1024);
        for (int ch = 0; ch < 3; ++ch) {
            std::printf("sun cosine %.2f channel %d: table %.4e, reference %.4e\n", sunDir.y, ch, got[i][ch], expected[ch]);
            EXPECT_NEAR(got[i][ch], expected[ch], kHemisphereBound * expected[ch]) << "sun cosine " << sunDir.y << " channel " << ch;
        }
    }
}

// Orders 2 to 4 over a black ground (the tables of 4 orders minus those of 1) against Monte
// Carlo path tracing (ReferenceAtmosphere::highOrderScattering, 20000 paths), at the points
// AtmosphereLutTest checks Yusov's high-order table at, case 2 (5 degrees above the horizon)
// included. Bound: 4 standard errors plus kHighOrderBound of the estimate (medium tables; the
// largest errors, 18-23%, are case 5's, a view near the zenith with the sun 2 degrees up).
TEST_F(BrunetonModel, HighOrderScatteringMatchesMonteCarlo) {
    const auto all = bruneton(LutResolution::Medium, 4, 0.0);
    const auto single = bruneton(LutResolution::Medium, 1, 0.0);
    const AtmosphereParameters& p = all->parameters().physics;
    const ReferenceAtmosphere reference(p);
    const HighOrderCases cases = highOrderCases(reference, p);
    const std::vector<Query>& queries = cases.queries;
    const std::vector<ReferenceAtmosphere::Estimate>& estimates = cases.estimates;
    const auto withAll = probe(*all, queries, "inscatter");
    const auto withSingle = probe(*single, queries, "inscatter");
    for (size_t i = 0; i < queries.size(); ++i) {
        const glm::dvec3 got = glm::dvec3(withAll[i]) - glm::dvec3(withSingle[i]);
        const auto& e = estimates[i];
        std::printf("case %zu: tables %.3e %.3e %.3e, Monte Carlo %.3e %.3e %.3e (+- %.1e %.1e %.1e)\n", i, got.r, got.g, got.b, e.mean.r,
                    e.mean.g, e.mean.b, e.standardError.r, e.standardError.g, e.standardError.b);
        for (int ch = 0; ch < 3; ++ch)
            EXPECT_NEAR(got[ch], e.mean[ch], 4.0 * e.standardError[ch] + kHighOrderBound * e.mean[ch]) << "case " << i << " channel " << ch;
    }
}

// The in-scatter table over a black ground at `points` random points (views within 2 degrees of
// the horizon left out), as Yusov's tables in AtmosphereLutTest: orders 2-4 (the tables of 4
// orders minus those of 1) against Monte Carlo with 400 paths each, and the whole table against
// that plus the reference's single scattering. The error beyond 4 standard errors, relative to
// the brightest channel or kRadianceFloor. Measured at 200 points: orders 2-4 median 0, 90th
// percentile 5.7%, largest 19% over rays of 5 km or more; the whole table 0, 10%, 29%. At the
// first 100 of them: 0, 5.8%, 19%; the whole table 0, 11%, 18%. (At the first 80 the 90th
// percentile of orders 2-4 read 11%, over its bound: the quick tier takes 100.) Steep rays to
// the ground from a few kilometres and less are up to 2-3 times off and left out of the largest:
// the 2008 u_mu maps distances under r - Rg onto the nadir texel, so they interpolate towards the
// next texel's much longer ray (docs/atmosphere.md, "Short rays to the ground").
void BrunetonModel::checkInscatterAtRandomPoints(int points) {
    constexpr double kMedian = 0.02, kNinetieth = 0.1, kLargest = 0.3, kShortRay = 5000.0;
    constexpr double kTotalMedian = 0.02, kTotalNinetieth = 0.15, kTotalLargest = 0.45;
    const auto all = bruneton(LutResolution::Medium, 4, 0.0);
    const auto single = bruneton(LutResolution::Medium, 1, 0.0);
    const ReferenceAtmosphere reference(all->parameters().physics);
    const QuerySet set = randomSkyQueries(all->parameters().physics, points, 32, 2.0);
    const std::vector<Query>& queries = set.queries;
    const auto withAll = probe(*all, queries, "inscatter");
    const auto withSingle = probe(*single, queries, "inscatter");
    std::vector<glm::dvec3> high, total;
    for (size_t i = 0; i < queries.size(); ++i) {
        high.push_back(glm::dvec3(withAll[i]) - glm::dvec3(withSingle[i]));
        total.emplace_back(withAll[i]);
    }
    const auto estimates = monteCarloHighOrders(reference, queries, 4, 400);
    const std::string at = " at " + std::to_string(points) + " points";
    expectHighOrderErrorsBelow(highOrderErrors(reference, high, estimates, kRadianceFloor, set, kShortRay),
                               ("Bruneton's orders 2-4 against Monte Carlo" + at).c_str(), kMedian, kNinetieth, kLargest);
    // The whole in-scatter table, orders 1 to 4, against the reference's single scattering plus
    // the same estimates.
    expectHighOrderErrorsBelow(highOrderErrors(reference, total, withSingleScattering(reference, queries, estimates), kRadianceFloor, set, kShortRay),
                               ("Bruneton's in-scatter table" + at).c_str(), kTotalMedian, kTotalNinetieth, kTotalLargest);
}

// The quick tier's: the first 100 of the full tier's 200 points (the same queries and paths).
TEST_F(BrunetonModel, InscatterAtAHundredRandomPointsMatchesTheReference) { checkInscatterAtRandomPoints(100); }

TEST_F(BrunetonModel, InscatterAtRandomPointsMatchesTheReference) { checkInscatterAtRandomPoints(200); }

// The ground's bounce: tables of orders 1 and 2 with albedo 0.3 minus the same with albedo 0
// is exactly the light reflected once by the ground and scattered once towards the viewer.
// The reference computes that by quadrature: along the view ray, over every direction w that
// meets the ground at g,
//   delta L = integral dt T(x -> y) sum of beta rho(y) P(v . w) a / pi T_sun(g) max(n_g . s, 0) T(y -> g) dw.
TEST_F(BrunetonModel, GroundBounceMatchesTheCpu) {
    constexpr double kAlbedo = 0.3;
    const auto bright = bruneton(LutResolution::Medium, 2, kAlbedo);
    const auto black = bruneton(LutResolution::Medium, 2, 0.0);
    const AtmosphereParameters& p = bright->parameters().physics;
    const ReferenceAtmosphere reference(p);
    struct Case { double altitude, viewElevation, sunElevation, azimuth; };
    const Case cases[] = {{2.0, 10.0, 30.0, 90.0}, {1000.0, 30.0, 45.0, 180.0}, {5000.0, -20.0, 40.0, 0.0}, {20000.0, -60.0, 20.0, 60.0}};
    std::vector<Query> queries;
    for (const Case& c : cases) {
        const double v = c.viewElevation * kPi / 180.0, s = c.sunElevation * kPi / 180.0, a = c.azimuth * kPi / 180.0;
        queries.push_back({glm::vec4(0.0f, static_cast<float>(p.earthRadius + c.altitude), 0.0f, 0.0f),
                           glm::vec4(static_cast<float>(std::cos(v)), static_cast<float>(std::sin(v)), 0.0f, 0.0f),
                           glm::vec4(static_cast<float>(std::cos(s) * std::cos(a)), static_cast<float>(std::sin(s)),
                                     static_cast<float>(std::cos(s) * std::sin(a)), 0.0f)});
    }
    const auto withGround = probe(*bright, queries, "inscatter");
    const auto without = probe(*black, queries, "inscatter");
    const auto directions = uniformSphereDirections(1024);
    for (size_t i = 0; i < queries.size(); ++i) {
        const glm::dvec3 x(queries[i].position), v(queries[i].viewDir), s(queries[i].sunDir);
        const double length = reference.rayLength(x, v);
        const auto bounceAt = [&](double t) {
            const glm::dvec3 y = x + v * t;
            const glm::dvec3 density = reference.density(glm::length(y) - p.earthRadius);
            glm::dvec3 sum(0.0);
            for (const glm::vec4& wf : directions) {
                const glm::dvec3 w(wf);
                if (!reference.hitsGround(y, w)) continue;
                const glm::dvec3 g = y + w * reference.rayLength(y, w);
                const glm::dvec3 normal = glm::normalize(g);
                const glm::dvec3 irradiance = reference.sunTransmittance(g + normal * 0.01, s) * std::max(glm::dot(normal, s), 0.0);
                const glm::dvec3 toGround = glm::exp(-reference.opticalDepth(reference.netDensity(y, g)));
                const double cosTheta = glm::dot(v, w);
                const glm::dvec3 scattering = p.rayleighScattering * density.x * atmosphere::rayleighPhase(cosTheta) +
                                              p.mieScattering * density.y * atmosphere::miePhase(cosTheta, p.mieAsymmetry);
                sum += scattering * kAlbedo / kPi * irradiance * toGround;
            }
            return sum * (4.0 * kPi / static_cast<double>(directions.size())) * glm::exp(-reference.opticalDepth(reference.netDensity(x, y)));
        };
        const glm::dvec3 expected = atmosphere::gaussLegendre3(bounceAt, 0.0, length, 4);
        const glm::dvec3 got = glm::dvec3(withGround[i]) - glm::dvec3(without[i]);
        std::printf("ground bounce case %zu: tables %.3e %.3e %.3e, reference %.3e %.3e %.3e\n", i, got.r, got.g, got.b, expected.r, expected.g,
                    expected.b);
        for (int ch = 0; ch < 3; ++ch) EXPECT_NEAR(got[ch], expected[ch], kBounceBound * expected[ch] + 2e-5) << "case " << i << " channel " << ch;
    }
}

// No NaN or Inf in any look-up from 0 to 1000 km with the sun anywhere, with the brightest
// ground (albedo 1) and four orders.
TEST_F(BrunetonModel, NoNanOrInfAnywhere) {
    const auto tables = bruneton(LutResolution::Small, 4, 1.0);
    const double R = tables->parameters().physics.earthRadius;
    const std::vector<Query> queries = extremeQueries(R);
    for (const char* entry : {"inscatter", "transmittance", "irradiance"}) {
        expectFiniteAndNotNegative(probe(*tables, queries, entry), entry);
    }
}

// The table files: what is written reads back bit for bit into fresh tables; a corrupt file,
// another key and other sizes are each refused with a reason, and nothing is changed then.
TEST_F(BrunetonModel, TableFilesRoundTripAndRefuseBadFiles) {
    const auto computed = bruneton(LutResolution::Small, 2, 0.2);
    BrunetonParameters bigger = computed->parameters();
    bigger.lut = atmosphere::bruneton::Dimensions::of(LutResolution::Medium);
    checkTableFiles<BrunetonPrecomputation>(device(), context(), *computed, brunetonTableKey(computed->parameters(), *productShaderLibrary), bigger,
                                            "bruneton-irradiance.exr", [&](const BrunetonPrecomputation& p) {
                                                const auto& t = p.tables();
                                                return std::vector{readTexture3D(device(), context(), t.inscatter.texture.Get()).bytes,
                                                                   readTexture2D(device(), context(), t.transmittance.texture.Get()).bytes,
                                                                   readTexture2D(device(), context(), t.irradiance.texture.Get()).bytes};
                                            });
}

// The sun's aureole with the sun 4 degrees up, from 300 m, views 6 to 45 degrees from it, single
// scattering: where Mie scattering dominates and the light is reddened. Bruneton's table keeps
// Mie's red channel exactly (alpha) and applies the phase functions at look-up, so its red
// matches the reference within kAureoleRedBound (measured 0.1%); its green and blue come from
// the red by the ratio of the species (mieFromRed), which a low sun's reddening breaks: up to
// 33% high here, a property of the 2008 model (kAureoleRebuiltBound bounds it). Yusov's table
// keeps each species in all three channels and applies the phases at look-up too: within
// kAureoleYusovBound (measured 0.4%; 9% when it stored the light with the phases applied, which
// blurred the Mie peak over 16 sun-view slices).
TEST_F(BrunetonModel, AureoleOfALowSun) {
    const auto b = bruneton(LutResolution::Full, 1, 0.0);
    const auto y = yusov(LutResolution::Full, 1);
    const AtmosphereParameters& p = y->parameters();
    const ReferenceAtmosphere reference(p);
    const double sunElevation = 4.0 * kPi / 180.0, viewElevation = 10.0 * kPi / 180.0;
    const glm::dvec3 sunDir(std::cos(sunElevation), std::sin(sunElevation), 0.0);
    std::vector<Query> queries;
    for (const double azimuth : {1.0, 3.0, 5.0, 8.0, 12.0, 20.0, 30.0, 45.0}) {
        const double a = azimuth * kPi / 180.0;
        const glm::dvec3 v(std::cos(viewElevation) * std::cos(a), std::sin(viewElevation), std::cos(viewElevation) * std::sin(a));
        queries.push_back({glm::vec4(0.0f, static_cast<float>(p.earthRadius + 300.0), 0.0f, 0.0f), glm::vec4(glm::vec3(v), 0.0f),
                           glm::vec4(glm::vec3(sunDir), 0.0f)});
    }
    const auto fromBruneton = probe(*b, queries, "inscatter");
    const auto fromYusov = probeYusov(*y, y->tables().singleScattering, queries);
    for (size_t i = 0; i < queries.size(); ++i) {
        const glm::dvec3 expected = reference.singleScattering(glm::dvec3(queries[i].position), glm::dvec3(queries[i].viewDir), sunDir);
        std::printf("%.1f degrees from the sun: reference %.4f %.4f %.4f, Yusov %.4f %.4f %.4f, Bruneton %.4f %.4f %.4f\n",
                    glm::degrees(std::acos(glm::dot(glm::dvec3(queries[i].viewDir), sunDir))), expected.r, expected.g, expected.b,
                    fromYusov[i].r, fromYusov[i].g, fromYusov[i].b, fromBruneton[i].r, fromBruneton[i].g, fromBruneton[i].b);
        EXPECT_NEAR(fromBruneton[i].r, expected.r, kAureoleRedBound * expected.r) << "query " << i;
        for (int ch = 1; ch < 3; ++ch) EXPECT_NEAR(fromBruneton[i][ch], expected[ch], kAureoleRebuiltBound * expected[ch]) << "query " << i;
        for (int ch = 0; ch < 3; ++ch) EXPECT_NEAR(fromYusov[i][ch], expected[ch], kAureoleYusovBound * expected[ch]) << "query " << i;
    }
}

// Bruneton 2008's zenith from high altitude is too bright, and the view zenith axis's mapping
// is why (the model's, kept; docs/atmosphere.md, "Bruneton's zenith from high altitude"). The sky
// half maps u_mu = d / (rho + H), d the distance to the top: from 40 km, rays shorter than the
// zenith's (60 km) do not exist, so the first rows all hold the zenith, the next one a view 45
// degrees down from it, and the zenith's look-up reads part of that much longer ray. Single
// scattering at the zenith from 40 km against the reference's integral: too bright by
// kZenithAt40Km (measured 18% with the Full tables' 128 rows of mu), and twice as much with half
// the rows (Medium, 64: measured 37%), as an error of the axis's spacing is; Yusov's tables
// (eq. 5 spends its rows by the horizon's angle) are within 3% there.
TEST_F(BrunetonModel, ZenithFromAltitudeFollowsTheViewAxisSpacing) {
    constexpr double kAltitude = 40000.0;
    const auto full = bruneton(LutResolution::Full, 1, 0.0), medium = bruneton(LutResolution::Medium, 1, 0.0);
    const auto y = yusov(LutResolution::Full, 1);
    const AtmosphereParameters& p = full->parameters().physics;
    const ReferenceAtmosphere reference(p);
    const double e = 60.0 * kPi / 180.0;
    const std::vector<Query> queries{{glm::vec4(0.0f, static_cast<float>(p.earthRadius + kAltitude), 0.0f, 0.0f), glm::vec4(0.0f, 1.0f, 0.0f, 0.0f),
                                      glm::vec4(static_cast<float>(std::cos(e)), static_cast<float>(std::sin(e)), 0.0f, 0.0f)}};
    const double expected = reference.singleScattering({kAltitude, 1.0, std::sin(e), std::sin(e)}).b;
    const double fromFull = probe(*full, queries, "inscatter")[0].b / expected - 1.0;
    const double fromMedium = probe(*medium, queries, "inscatter")[0].b / expected - 1.0;
    const double fromYusov = probeYusov(*y, y->tables().singleScattering, queries)[0].b / expected - 1.0;
    std::printf("zenith from 40 km, single scattering, against the reference: Bruneton Full %+.3f, Medium %+.3f; Yusov Full %+.3f\n", fromFull,
                fromMedium, fromYusov);
    EXPECT_GT(fromFull, kZenithAt40Km.first);
    EXPECT_LT(fromFull, kZenithAt40Km.second);
    EXPECT_GT(fromMedium / fromFull, 1.6);
    EXPECT_LT(fromMedium / fromFull, 2.4);
    EXPECT_LT(std::abs(fromYusov), 0.03);
}

}  // namespace
}  // namespace firmament::test
