// Hillaire 2020's tables on the GPU: the parameterization's HLSL
// (shaders/atmosphere/hillaire/parameterization.hlsli) against its CPU twin
// (src/atmosphere/hillaire/HillaireParameterization), forward and back, from the ground to the
// top of the atmosphere, in single precision; the transmittance table against the reference
// atmosphere; the multiple-scattering table against its CPU twin.
#include "AtmosphereQueries.h"
#include "WarpDevice.h"
#include "atmosphere/AtmosphereStructures.h"
#include "atmosphere/hillaire/HillaireParameterization.h"
#include "atmosphere/hillaire/HillairePrecomputation.h"
#include "gpu/ConstantBuffer.h"
#include "gpu/Readback.h"
#include "reference/HillaireMultipleScatteringTwin.h"
#include "reference/ReferenceAtmosphere.h"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <cstring>
#include <vector>

namespace firmament::test {
namespace {

namespace hillaire = atmosphere::hillaire;

class HillaireTables : public WarpDevice {
protected:
    std::vector<glm::vec4> probe(const AtmosphereParameters& p, const std::vector<Query>& queries, const char* entry) {
        ConstantBuffer<gpu::AtmosphereConstants> constants(device());
        constants.update(context(), p.constants());
        return runProbe({"atmosphere/hillaire_probe.hlsl", entry, "cs_5_0", {}}, queries, {constants.get()}, {}, nullptr);
    }

    std::unique_ptr<HillairePrecomputation> precompute(const HillaireParameters& parameters) {
        auto tables = std::make_unique<HillairePrecomputation>(device(), parameters);
        tables->runAll(context(), *productShaderLibrary);
        return tables;
    }

    // Texel (x, y) of an R32G32B32A32_FLOAT table, RGB.
    static glm::dvec3 texel(const ReadbackImage& image, int x, int y) {
        float rgba[4];
        std::memcpy(rgba, image.bytes.data() + (static_cast<size_t>(y) * image.width + x) * sizeof(rgba), sizeof(rgba));
        return {rgba[0], rgba[1], rgba[2]};
    }
};

// The cosine of the angle between the horizontal parts of the view and the sun at `up`.
double cosAzimuth(glm::dvec3 up, glm::dvec3 view, glm::dvec3 sun) {
    const glm::dvec3 a = view - glm::dot(view, up) * up, b = sun - glm::dot(sun, up) * up;
    return glm::length(a) > 0.0 && glm::length(b) > 0.0 ? glm::dot(glm::normalize(a), glm::normalize(b)) : 1.0;
}

// Unit coordinates within 3e-4 of the CPU's (the GPU keeps 24 bits; near the horizon the sky
// view's square root magnifies an angle's last bits), over altitudes from 2 m to the top, views
// from the zenith to the nadir (not exactly along the horizon) and suns all around.
TEST_F(HillaireTables, ParameterizationMatchesTheCpu) {
    const AtmosphereParameters p;
    constexpr double kUnitBound = 3e-4;
    std::vector<Query> queries;
    for (const double altitude : {2.0, 100.0, 1000.0, 10.0e3, 40.0e3, 79.0e3})
        for (const double mu : {1.0, 0.7, 0.2, 0.05, -0.05, -0.3, -0.9})
            for (const double sunAzimuth : {0.0, 1.0, 2.5}) {
                const double r = p.earthRadius + altitude;
                const glm::dvec3 view(std::sqrt(1.0 - mu * mu), mu, 0.0);
                const glm::dvec3 sun(0.6 * std::cos(sunAzimuth), 0.8, 0.6 * std::sin(sunAzimuth));
                queries.push_back({glm::vec4(0.0f, static_cast<float>(r), 0.0f, 0.0f), glm::vec4(glm::vec3(view), 0.0f), glm::vec4(glm::vec3(sun), 0.0f)});
            }
    const std::vector<glm::vec4> forward = probe(p, queries, "forward"), multiple = probe(p, queries, "multiple");
    for (size_t i = 0; i < queries.size(); ++i) {
        const Query& q = queries[i];
        const double r = q.position.y, mu = q.viewDir.y;
        const glm::dvec2 transmittance = hillaire::transmittanceUnit(p, r, mu);
        const glm::dvec2 sky = hillaire::skyViewUnit(p, r, mu, cosAzimuth({0.0, 1.0, 0.0}, glm::dvec3(q.viewDir), glm::dvec3(q.sunDir)));
        const glm::dvec2 ms = hillaire::multipleScatteringUnit(p, r, q.sunDir.y);
        EXPECT_NEAR(forward[i].x, transmittance.x, kUnitBound) << "query " << i;
        EXPECT_NEAR(forward[i].y, transmittance.y, kUnitBound) << "query " << i;
        EXPECT_NEAR(forward[i].z, sky.x, kUnitBound) << "query " << i;
        EXPECT_NEAR(forward[i].w, sky.y, kUnitBound) << "query " << i;
        EXPECT_NEAR(multiple[i].x, ms.x, kUnitBound) << "query " << i;
        EXPECT_NEAR(multiple[i].y, ms.y, kUnitBound) << "query " << i;
    }
    // The inverses at a grid of unit coordinates, from 1 km: radius within 2 m, cosines within 3e-4.
    std::vector<Query> units;
    for (double u = 0.0; u <= 1.0; u += 0.125)
        for (double v = 0.0; v <= 1.0; v += 0.125)
            units.push_back({glm::vec4(0.0f, static_cast<float>(p.earthRadius + 1000.0), 0.0f, 0.0f), glm::vec4(float(u), float(v), 0.0f, 0.0f),
                             glm::vec4(0.0f)});
    const std::vector<glm::vec4> inverse = probe(p, units, "inverse");
    for (size_t i = 0; i < units.size(); ++i) {
        const glm::dvec2 unit(units[i].viewDir.x, units[i].viewDir.y);
        const hillaire::RadiusAndCosine t = hillaire::transmittanceCoordinates(p, unit);
        const hillaire::SkyViewDirection d = hillaire::skyViewDirection(p, p.earthRadius + 1000.0, unit);
        EXPECT_NEAR(inverse[i].x, t.r, 2.0) << "unit " << unit.x << "," << unit.y;
        EXPECT_NEAR(inverse[i].y, t.mu, kUnitBound) << "unit " << unit.x << "," << unit.y;
        EXPECT_NEAR(inverse[i].z, d.mu, kUnitBound) << "unit " << unit.x << "," << unit.y;
        EXPECT_NEAR(inverse[i].w, d.cosAzimuth, kUnitBound) << "unit " << unit.x << "," << unit.y;
    }
}

// Every texel of the transmittance table (the paper's 256 x 64) against the reference's
// exp(-optical depth) to the top (Gauss-Legendre quadrature in double precision): within 1e-4.
// Measured: the largest difference is printed.
TEST_F(HillaireTables, TransmittanceMatchesTheReference) {
    constexpr double kBound = 1e-4;
    HillaireParameters parameters;
    const auto tables = precompute(parameters);
    const AtmosphereParameters& p = parameters.physics;
    const atmosphere::ReferenceAtmosphere reference(p);
    const ReadbackImage image = readTexture2D(device(), context(), tables->tables().transmittance.texture.Get());
    double largest = 0.0;
    for (int y = 0; y < image.height; ++y)
        for (int x = 0; x < image.width; ++x) {
            const hillaire::RadiusAndCosine c =
                hillaire::transmittanceCoordinates(p, {x / (image.width - 1.0), y / (image.height - 1.0)});
            const glm::dvec3 expected = glm::exp(-reference.opticalDepth(reference.netDensityToTop(c.r - p.earthRadius, c.mu)));
            const glm::dvec3 got = texel(image, x, y);
            for (int ch = 0; ch < 3; ++ch) {
                largest = std::max(largest, std::abs(got[ch] - expected[ch]));
                ASSERT_NEAR(got[ch], expected[ch], kBound) << "texel " << x << "," << y << " (h " << c.r - p.earthRadius << " m, mu " << c.mu << ")";
            }
        }
    std::printf("transmittance: largest difference from the reference %.2e over %dx%d texels\n", largest, image.width, image.height);
}

// The multiple-scattering table (the paper's 32 x 32, 64 directions of 20 steps), and the same
// table twice as fine (the Atmosphere panel's detail 2: 64 x 64), against its CPU twin at 64 of
// their texels: relative to the brightest channel, within 2%. The GPU reads the sun's
// transmittance from its table and integrates T(x, y) on sub-steps; the twin computes both by
// quadrature. The settings' detail multiplies both axes of whichever LUT resolution is chosen.
TEST_F(HillaireTables, MultipleScatteringMatchesItsCpuTwin) {
    constexpr double kBound = 0.02;
    for (int detail : {1, 2}) {
        AtmosphereSettings settings;
        settings.hillaireMultipleScatteringDetail = detail;
        const HillaireParameters parameters = HillaireParameters::from(settings);
        ASSERT_EQ(parameters.lut.multipleScatteringMuS, 32 * detail);
        ASSERT_EQ(parameters.lut.multipleScatteringR, 32 * detail);
        settings.resolution = LutResolution::Small;
        EXPECT_EQ(HillaireParameters::from(settings).lut.multipleScatteringMuS, 16 * detail);
        const auto tables = precompute(parameters);
        const AtmosphereParameters& p = parameters.physics;
        const atmosphere::ReferenceAtmosphere reference(p);
        const ReadbackImage image = readTexture2D(device(), context(), tables->tables().multipleScattering.texture.Get());
        ASSERT_EQ(image.width, 32 * detail);
        const int stride = 4 * detail;
        double largest = 0.0;
        for (int y = 0; y < image.height; y += stride)
            for (int x = 0; x < image.width; x += stride) {
                const hillaire::RadiusAndCosine c =
                    hillaire::multipleScatteringCoordinates(p, {x / (image.width - 1.0), y / (image.height - 1.0)});
                const glm::dvec3 expected = atmosphere::hillaireMultipleScattering(reference, c.r, c.mu).psi;
                const glm::dvec3 got = texel(image, x, y);
                const double scale = std::max({expected.r, expected.g, expected.b, 1e-6});
                for (int ch = 0; ch < 3; ++ch) {
                    const double error = std::abs(got[ch] - expected[ch]) / scale;
                    largest = std::max(largest, error);
                    EXPECT_LT(error, kBound) << "detail " << detail << ", texel " << x << "," << y << " (h " << c.r - p.earthRadius << " m, mu_s "
                                             << c.mu << ") channel " << ch << ": " << got[ch] << " against " << expected[ch];
                }
            }
        std::printf("multiple scattering %dx%d: largest difference from the CPU twin %.4f of the brightest channel\n", image.width, image.height,
                    largest);
    }
}

}  // namespace
}  // namespace firmament::test
