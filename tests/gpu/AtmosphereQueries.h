#pragma once
// Points at which the atmosphere tests read the tables: a position relative to the Earth's
// centre, a view and a sun direction, laid out as the probe shaders' Query structure.
#include "atmosphere/AtmosphereParameters.h"
#include "atmosphere/yusov/YusovParameterization.h"
#include "reference/ReferenceAtmosphere.h"

#include <glm/glm.hpp>
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <random>
#include <vector>

namespace firmament::test {

struct Query {
    glm::vec4 position, viewDir, sunDir;
};

struct QuerySet {
    std::vector<Query> queries;
    std::vector<atmosphere::ScatteringCoordinates> coordinates;  // the same points as table coordinates
};

// `count` random points: altitudes crowded near the ground (u^2 H_atm), views uniform in the
// sine of their elevation but never within `horizonBandDegrees` of the horizon, suns from -10 to
// 90 degrees of elevation at any azimuth.
inline QuerySet randomSkyQueries(const AtmosphereParameters& p, size_t count, unsigned seed, double horizonBandDegrees) {
    constexpr double kPi = 3.14159265358979323846;
    std::mt19937 random(seed);
    std::uniform_real_distribution<double> unit(0.0, 1.0);
    QuerySet set;
    while (set.queries.size() < count) {
        const double u = unit(random);
        const double h = u * u * p.atmosphereHeight;
        const double viewElevation = std::asin(unit(random) * 2.0 - 1.0);
        const double horizonElevation = std::asin(atmosphere::cosHorizon(p, h));
        if (std::abs(viewElevation - horizonElevation) < horizonBandDegrees * kPi / 180.0) continue;
        const double sunElevation = (-10.0 + 100.0 * unit(random)) * kPi / 180.0;
        const double sunAzimuth = unit(random) * 2.0 * kPi;
        const glm::dvec3 viewDir(std::cos(viewElevation), std::sin(viewElevation), 0.0);
        const glm::dvec3 sunDir(std::cos(sunElevation) * std::cos(sunAzimuth), std::sin(sunElevation), std::cos(sunElevation) * std::sin(sunAzimuth));
        const glm::dvec3 position(0.0, p.earthRadius + h, 0.0);
        set.queries.push_back({glm::vec4(glm::vec3(position), 0.0f), glm::vec4(glm::vec3(viewDir), 0.0f), glm::vec4(glm::vec3(sunDir), 0.0f)});
        set.coordinates.push_back({h, viewDir.y, sunDir.y, glm::dot(viewDir, sunDir)});
    }
    return set;
}

// `count` random points for the sun's transmittance: altitudes u^2 H_atm, sun elevations
// uniform in their sine (the horizon included).
inline std::vector<Query> randomSunQueries(const AtmosphereParameters& p, int count, unsigned seed) {
    std::mt19937 random(seed);
    std::uniform_real_distribution<double> unit(0.0, 1.0);
    std::vector<Query> queries;
    for (int i = 0; i < count; ++i) {
        const double h = std::pow(unit(random), 2.0) * p.atmosphereHeight;
        const double elevation = std::asin(unit(random) * 2.0 - 1.0);
        queries.push_back({glm::vec4(0.0f, static_cast<float>(p.earthRadius + h), 0.0f, 0.0f), glm::vec4(0.0f),
                           glm::vec4(static_cast<float>(std::cos(elevation)), static_cast<float>(std::sin(elevation)), 0.0f, 0.0f)});
    }
    return queries;
}

// The largest absolute error of the sun's transmittance at `queries` against the reference;
// each channel of each query is also expected within `bound`.
inline double sunTransmittanceError(const atmosphere::ReferenceAtmosphere& reference, const std::vector<Query>& queries,
                                    const std::vector<glm::vec4>& got, double bound) {
    double worst = 0.0;
    for (size_t i = 0; i < queries.size(); ++i) {
        const glm::dvec3 expected = reference.sunTransmittance(glm::dvec3(queries[i].position), glm::dvec3(queries[i].sunDir));
        for (int ch = 0; ch < 3; ++ch) {
            const double error = std::abs(got[i][ch] - expected[ch]);
            worst = std::max(worst, error);
            EXPECT_LT(error, bound) << "query " << i << " altitude " << queries[i].position.y - reference.parameters().earthRadius << " sun y "
                                    << queries[i].sunDir.y << ": " << got[i][ch] << " vs " << expected[ch];
        }
    }
    return worst;
}

// The median, 90th percentile and largest of a set of errors.
struct Percentiles {
    double median, ninetieth, largest;
};

inline Percentiles percentiles(std::vector<double> errors) {
    std::sort(errors.begin(), errors.end());
    return {errors[errors.size() / 2], errors[errors.size() * 9 / 10], errors.back()};
}

// `e`, printed as `what`'s errors, held below the three bounds.
inline void expectPercentilesBelow(const Percentiles& e, const char* what, double median, double ninetieth, double largest) {
    std::printf("%s: median %.4f, 90th percentile %.4f, largest %.4f\n", what, e.median, e.ninetieth, e.largest);
    EXPECT_LT(e.median, median) << what;
    EXPECT_LT(e.ninetieth, ninetieth) << what;
    EXPECT_LT(e.largest, largest) << what;
}

// `count` random points for the sky's irradiance: altitudes u^2 `maxAltitude`, sun zenith
// cosines uniform in [-0.2, 1] (below, the sky is dark), the sun at any azimuth.
inline std::vector<Query> randomIrradianceQueries(const AtmosphereParameters& p, int count, unsigned seed, double maxAltitude) {
    constexpr double kPi = 3.14159265358979323846;
    std::mt19937 random(seed);
    std::uniform_real_distribution<double> unit(0.0, 1.0);
    std::vector<Query> queries;
    for (int i = 0; i < count; ++i) {
        const double h = std::pow(unit(random), 2.0) * maxAltitude;
        const double cosSun = -0.2 + 1.2 * unit(random), azimuth = 2.0 * kPi * unit(random);
        const double sinSun = std::sqrt(1.0 - cosSun * cosSun);
        queries.push_back({glm::vec4(0.0f, static_cast<float>(p.earthRadius + h), 0.0f, 0.0f), glm::vec4(0.0f),
                           glm::vec4(static_cast<float>(sinSun * std::cos(azimuth)), static_cast<float>(cosSun),
                                     static_cast<float>(sinSun * std::sin(azimuth)), 0.0f)});
    }
    return queries;
}

// Sky irradiance from a table at `queries` against the reference's Monte Carlo (orders 1 to
// maxOrder, `paths` each): per point the error beyond 4 standard errors relative to the
// brightest channel of the estimate or `floor`; printing those over 10%.
inline Percentiles irradianceErrors(const atmosphere::ReferenceAtmosphere& reference, const std::vector<Query>& queries,
                                            const std::vector<glm::dvec3>& table, int maxOrder, int paths, double floor) {
    std::vector<double> errors;
    for (size_t i = 0; i < queries.size(); ++i) {
        const auto e = reference.skyIrradiance(glm::dvec3(queries[i].position), glm::dvec3(queries[i].sunDir), maxOrder, paths,
                                               2000u + static_cast<unsigned>(i));
        const double scale = std::max({e.mean.r, e.mean.g, e.mean.b, floor});
        double error = 0.0;
        for (int ch = 0; ch < 3; ++ch) error = std::max(error, std::max(0.0, std::abs(table[i][ch] - e.mean[ch]) - 4.0 * e.standardError[ch]) / scale);
        errors.push_back(error);
        if (error > 0.1)
            std::printf("  point %zu (h %.0f, sun %.3f): table %.3e %.3e %.3e, Monte Carlo %.3e %.3e %.3e (+- %.1e %.1e %.1e)\n", i,
                        queries[i].position.y - reference.parameters().earthRadius, queries[i].sunDir.y, table[i].r, table[i].g, table[i].b,
                        e.mean.r, e.mean.g, e.mean.b, e.standardError.r, e.standardError.g, e.standardError.b);
    }
    return percentiles(errors);
}

// Points from the ground to 1000 km (above the atmosphere), looking every 15 degrees from the
// zenith to the nadir, with the sun every 5 degrees from the zenith to the nadir: where a
// look-up could produce NaN or Inf.
inline std::vector<Query> extremeQueries(double earthRadius) {
    constexpr double kPi = 3.14159265358979323846;
    std::vector<Query> queries;
    for (const double h : {0.0, 1.0, 100.0, 10.0e3, 79.9e3, 80.0e3, 200.0e3, 1000.0e3})
        for (int sun = 0; sun <= 36; ++sun)
            for (int view = 0; view <= 12; ++view) {
                const double sunZenith = sun * kPi / 36.0, viewZenith = view * kPi / 12.0;
                queries.push_back({glm::vec4(0.0f, static_cast<float>(earthRadius + h), 0.0f, 0.0f),
                                   glm::vec4(static_cast<float>(std::sin(viewZenith)), static_cast<float>(std::cos(viewZenith)), 0.0f, 0.0f),
                                   glm::vec4(0.0f, static_cast<float>(std::cos(sunZenith)), static_cast<float>(std::sin(sunZenith)), 0.0f)});
            }
    return queries;
}

// Orders 2 to maxOrder by the reference's Monte Carlo at each query (seeds 1000 + i).
inline std::vector<atmosphere::ReferenceAtmosphere::Estimate> monteCarloHighOrders(const atmosphere::ReferenceAtmosphere& reference,
                                                                                 const std::vector<Query>& queries, int maxOrder, int paths) {
    std::vector<atmosphere::ReferenceAtmosphere::Estimate> estimates;
    for (size_t i = 0; i < queries.size(); ++i)
        estimates.push_back(reference.highOrderScattering(glm::dvec3(queries[i].position), glm::dvec3(queries[i].viewDir),
                                                          glm::dvec3(queries[i].sunDir), maxOrder, paths, 1000u + static_cast<unsigned>(i)));
    return estimates;
}

// The same estimates with the reference's single scattering added: all orders 1 to N.
inline std::vector<atmosphere::ReferenceAtmosphere::Estimate> withSingleScattering(const atmosphere::ReferenceAtmosphere& reference,
                                                                                 const std::vector<Query>& queries,
                                                                                 std::vector<atmosphere::ReferenceAtmosphere::Estimate> estimates) {
    for (size_t i = 0; i < queries.size(); ++i)
        estimates[i].mean += reference.singleScattering(glm::dvec3(queries[i].position), glm::dvec3(queries[i].viewDir), glm::dvec3(queries[i].sunDir));
    return estimates;
}

// A table's high orders against Monte Carlo estimates: per point the error beyond 4 standard
// errors, relative to the brightest channel of the estimate (or `floor`). The median and 90th
// percentile over every point; the largest over the rays longer than `shortRay` metres (rays
// to the ground from a few hundred metres fall between the tables' first altitude layers, or
// near the nadir between their first view texels, and are 2-3 times off: see
// docs/atmosphere.md). Points off by more than 30% are printed.
struct HighOrderErrors {
    double median, ninetieth, largestLongRay;
};

inline HighOrderErrors highOrderErrors(const atmosphere::ReferenceAtmosphere& reference, const std::vector<glm::dvec3>& table,
                                       const std::vector<atmosphere::ReferenceAtmosphere::Estimate>& estimates, double floor,
                                       const QuerySet& set, double shortRay) {
    std::vector<double> errors;
    double largest = 0.0;
    for (size_t i = 0; i < table.size(); ++i) {
        const auto& e = estimates[i];
        const double scale = std::max({e.mean.r, e.mean.g, e.mean.b, floor});
        double error = 0.0;
        for (int ch = 0; ch < 3; ++ch) error = std::max(error, std::max(0.0, std::abs(table[i][ch] - e.mean[ch]) - 4.0 * e.standardError[ch]) / scale);
        errors.push_back(error);
        const Query& q = set.queries[i];
        const double length = reference.rayLength(glm::dvec3(q.position), glm::dvec3(q.viewDir));
        if (length >= shortRay) largest = std::max(largest, error);
        if (error > 0.3)
            std::printf("  point %zu (h %.0f, view %.3f, sun %.3f, sun-view %.3f, ray %.0f m): table %.3e %.3e %.3e, Monte Carlo %.3e %.3e %.3e\n", i,
                        set.coordinates[i].altitude, set.coordinates[i].cosView, set.coordinates[i].cosSun, set.coordinates[i].cosSunView, length,
                        table[i].r, table[i].g, table[i].b, e.mean.r, e.mean.g, e.mean.b);
    }
    const Percentiles all = percentiles(errors);
    return {all.median, all.ninetieth, largest};
}

// `e`, printed as `what`'s errors, held below the three bounds (the largest over the long rays).
inline void expectHighOrderErrorsBelow(const HighOrderErrors& e, const char* what, double median, double ninetieth, double largestLongRay) {
    std::printf("%s: median %.4f, 90th percentile %.4f, largest (rays over 5 km) %.4f\n", what, e.median, e.ninetieth, e.largestLongRay);
    EXPECT_LT(e.median, median) << what;
    EXPECT_LT(e.ninetieth, ninetieth) << what;
    EXPECT_LT(e.largestLongRay, largestLongRay) << what;
}

// Six views at which both models' higher orders are held to Monte Carlo (20000 paths each, orders
// 2 to 4): from the ground looking up, across and 5 degrees above the horizon, from 5 and 30 km,
// and near the zenith with the sun 2 degrees up.
struct HighOrderCases {
    std::vector<Query> queries;
    std::vector<atmosphere::ReferenceAtmosphere::Estimate> estimates;
};

inline HighOrderCases highOrderCases(const atmosphere::ReferenceAtmosphere& reference, const AtmosphereParameters& p) {
    struct Case {
        double altitude, viewElevation, sunElevation, azimuth;
    };
    const Case cases[] = {{2.0, 30.0, 30.0, 90.0}, {2.0, 60.0, 10.0, 180.0}, {2.0, 5.0, 45.0, 40.0},
                          {5000.0, 20.0, 60.0, 120.0}, {30000.0, 10.0, 20.0, 60.0}, {2.0, 80.0, 2.0, 0.0}};
    constexpr double kDegree = 3.14159265358979323846 / 180.0;
    HighOrderCases out;
    for (const Case& c : cases) {
        const double v = c.viewElevation * kDegree, s = c.sunElevation * kDegree, a = c.azimuth * kDegree;
        const glm::dvec3 position(0.0, p.earthRadius + c.altitude, 0.0), viewDir(std::cos(v), std::sin(v), 0.0);
        const glm::dvec3 sunDir(std::cos(s) * std::cos(a), std::sin(s), std::cos(s) * std::sin(a));
        out.queries.push_back({glm::vec4(glm::vec3(position), 0.0f), glm::vec4(glm::vec3(viewDir), 0.0f), glm::vec4(glm::vec3(sunDir), 0.0f)});
        out.estimates.push_back(reference.highOrderScattering(position, viewDir, sunDir, 4, 20000, 11u + static_cast<unsigned>(out.estimates.size())));
    }
    return out;
}

// No NaN, no infinity and no negative light in any channel of `got` (the probe's `entry`).
inline void expectFiniteAndNotNegative(const std::vector<glm::vec4>& got, const char* entry) {
    for (size_t i = 0; i < got.size(); ++i)
        for (int ch = 0; ch < 3; ++ch) ASSERT_TRUE(std::isfinite(got[i][ch]) && got[i][ch] >= 0.0f) << entry << " query " << i;
}

// Twilight below the tables' lowest sun: the zenith seen from 2 m with the sun 8 to 20 degrees
// down, a degree apart.
inline std::vector<Query> twilightZenithQueries(const AtmosphereParameters& p) {
    std::vector<Query> queries;
    for (int degrees = -8; degrees >= -20; --degrees) {
        const double e = degrees * 3.14159265358979323846 / 180.0;
        queries.push_back({glm::vec4(0.0f, static_cast<float>(p.earthRadius + 2.0), 0.0f, 0.0f), glm::vec4(0.0f, 1.0f, 0.0f, 0.0f),
                           glm::vec4(static_cast<float>(std::cos(e)), static_cast<float>(std::sin(e)), 0.0f, 0.0f)});
    }
    return queries;
}

// The zenith's light at twilightZenithQueries falls at every degree, by a factor of 1.5 or more
// from 12 degrees down, so that at 18 degrees down it is under 2% of that at 12.
inline void expectTwilightFalls(const std::vector<glm::vec4>& got) {
    const auto luminance = [](glm::vec4 c) { return 0.2126 * c.r + 0.7152 * c.g + 0.0722 * c.b; };
    for (size_t i = 0; i + 1 < got.size(); ++i) {
        const int degrees = -8 - static_cast<int>(i);
        std::printf("sun %d degrees: zenith %.3e\n", degrees, luminance(got[i]));
        EXPECT_TRUE(std::isfinite(luminance(got[i])) && luminance(got[i]) >= 0.0) << degrees;
        EXPECT_LT(luminance(got[i + 1]), luminance(got[i])) << "from " << degrees << " to " << degrees - 1 << " degrees";
        if (degrees <= -12) {
            EXPECT_LT(luminance(got[i + 1]) * 1.5, luminance(got[i])) << "from " << degrees << " to " << degrees - 1 << " degrees";
        }
    }
    EXPECT_LT(luminance(got[10]), 0.02 * luminance(got[4]));  // -18 against -12 degrees
}

// The largest channel error relative to the brightest channel of `expected`, or to `floor`
// where that is darker.
inline double errorRelativeToBrightest(glm::dvec3 got, glm::dvec3 expected, double floor) {
    const double scale = std::max({expected.r, expected.g, expected.b, floor});
    double error = 0.0;
    for (int ch = 0; ch < 3; ++ch) error = std::max(error, std::abs(got[ch] - expected[ch]) / scale);
    return error;
}

}  // namespace firmament::test
