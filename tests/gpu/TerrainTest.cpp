// The terrain's shader functions on the WARP device against their CPU twins and the physics:
// the surface (height field, detail noise, the Earth's curvature) against TerrainSurface.cpp, and
// the shading (Yusov 2013's terrain lighting) against the reference atmosphere's transmittance
// and Monte Carlo sky irradiance.
#include "gpu/WarpDevice.h"

#include "atmosphere/AtmosphereParameters.h"
#include "atmosphere/bruneton/BrunetonPrecomputation.h"
#include "atmosphere/hillaire/HillairePrecomputation.h"
#include "atmosphere/yusov/YusovPrecomputation.h"
#include "gpu/CommonStates.h"
#include "gpu/ConstantBuffer.h"
#include "reference/ReferenceAtmosphere.h"
#include "terrain/Terrain.h"
#include "terrain/TerrainGenerator.h"
#include "terrain/TerrainSurface.h"

#include <algorithm>
#include <cstdio>
#include <random>

namespace firmament::test {
namespace {

using atmosphere::ReferenceAtmosphere;
constexpr double kPi = 3.14159265358979323846;

struct ProbeQuery {
    glm::vec4 a, b, c, d;
};

class TerrainFunctions : public WarpDevice {
protected:
    gpu::TerrainConstants fieldConstants(const HeightField& field, double earthRadius) {
        gpu::TerrainConstants c{};
        c.field = glm::vec4(static_cast<float>(field.spacing()), static_cast<float>(field.size()), 1.0f / static_cast<float>(field.size()),
                            static_cast<float>(earthRadius));
        return c;
    }
};

// Height above the sphere at random points, vertex spacings and mips, within a millimetre of the
// CPU twin (float against double at coordinates up to 60 km), and its three parts apart.
TEST_F(TerrainFunctions, SurfaceMatchesTheCpuTwin) {
    TerrainGeneratorParameters p;
    p.size = 256;
    p.spacing = 16.0;
    const double R = AtmosphereParameters{}.earthRadius;
    Terrain terrain(device(), HeightField(generateHeights(p), p.size, p.spacing), R);
    const HeightField& field = terrain.heightField();
    std::mt19937 random(5);
    std::uniform_real_distribution<double> coordinate(-60000.0, 60000.0);
    std::vector<ProbeQuery> queries;
    for (int i = 0; i < 400; ++i) {
        const double spacing = std::ldexp(1.0, static_cast<int>(random() % 12));
        const float x = static_cast<float>(coordinate(random)), z = static_cast<float>(coordinate(random));
        queries.push_back({glm::vec4(x, z, static_cast<float>(spacing), static_cast<float>(heightMipFor(spacing, field))), {}, {}, {}});
    }
    ConstantBuffer<gpu::TerrainConstants> constants(device());
    constants.update(context(), fieldConstants(field, R));
    const auto sampler = states::linearClamp(device());
    const auto results = runProbe({"terrain/terrain_probe.hlsl", "surface", "cs_5_0", {}}, queries, {nullptr, nullptr, constants.get()},
                                  {terrain.heightFieldView(), nullptr, nullptr}, sampler.Get());
    double largest = 0.0;
    for (size_t i = 0; i < queries.size(); ++i) {
        const double x = queries[i].a.x, z = queries[i].a.y, spacing = queries[i].a.z;
        const int mip = static_cast<int>(queries[i].a.w);
        const double field_ = field.sample(x, z, mip), detail = detailHeight(x, z, spacing);
        EXPECT_NEAR(results[i].y, field_, 2e-3) << "height field at " << x << ", " << z << " mip " << mip;
        EXPECT_NEAR(results[i].z, detail, 1e-4) << "detail at " << x << ", " << z << " spacing " << spacing;
        EXPECT_NEAR(results[i].w, earthDrop(x, z, R), 1e-6 * earthDrop(x, z, R) + 1e-3) << "drop at " << x << ", " << z;
        // The range mask is evaluated in float 85 to 390 km from its lattice's origin (its
        // offset): about 1e-6 of the height, 5 mm on a 3.3 km summit.
        EXPECT_NEAR(results[i].x, surfaceHeight(field, x, z, spacing), 5e-3);
        largest = std::max(largest, std::abs(results[i].x - surfaceHeight(field, x, z, spacing)));
    }
    std::printf("terrain surface: largest difference from the CPU twin %.2e m over %zu points\n", largest, queries.size());
}

// Random points of the ground: altitude, sun, a surface normal tilted up to 60 degrees, albedo,
// and the sun seen or shadowed.
std::vector<ProbeQuery> shadingQueries(int count, double maxAltitude, unsigned seed) {
    std::mt19937 random(seed);
    std::uniform_real_distribution<double> unit(0.0, 1.0);
    std::vector<ProbeQuery> queries;
    for (int i = 0; i < count; ++i) {
        const double h = unit(random) * maxAltitude;
        const double cosSun = -0.15 + 1.15 * unit(random), sunAzimuth = 2.0 * kPi * unit(random);
        const double tilt = std::acos(1.0 - unit(random) * 0.5), tiltAzimuth = 2.0 * kPi * unit(random);
        const glm::dvec3 sun(std::sqrt(1.0 - cosSun * cosSun) * std::cos(sunAzimuth), cosSun, std::sqrt(1.0 - cosSun * cosSun) * std::sin(sunAzimuth));
        const glm::dvec3 normal(std::sin(tilt) * std::cos(tiltAzimuth), std::cos(tilt), std::sin(tilt) * std::sin(tiltAzimuth));
        const glm::vec3 albedo(0.1 + 0.8 * unit(random), 0.1 + 0.8 * unit(random), 0.1 + 0.8 * unit(random));
        const float visibility = (i % 3 == 0) ? 0.0f : 1.0f;
        queries.push_back({glm::vec4(albedo, static_cast<float>(h)), glm::vec4(glm::vec3(normal), visibility), glm::vec4(0, 1, 0, 0),
                           glm::vec4(glm::vec3(sun), 0.0f)});
    }
    return queries;
}

// The shading's two terms against the reference: the sun's, albedo / pi * T * max(N.L, 0) *
// visibility with T the reference's exact transmittance (within the tables' own 1% plus
// filtering), and the sky's, albedo / pi * E_sky * (1 + N.up) / 2 with E_sky the reference's
// Monte Carlo irradiance (4 orders, the percentiles of the tables' own tests).
void checkShading(const std::vector<ProbeQuery>& queries, const std::vector<glm::vec4>& withSky, const std::vector<glm::vec4>& skyOnly,
                  const ReferenceAtmosphere& reference, double earthRadius, const char* model) {
    double largestSun = 0.0;
    std::vector<double> skyErrors;
    for (size_t i = 0; i < queries.size(); ++i) {
        const ProbeQuery& q = queries[i];
        const glm::dvec3 albedo(q.a), normal(q.b), up(q.c), sun(q.d);
        const glm::dvec3 position(0.0, earthRadius + q.a.w, 0.0);
        const glm::dvec3 sunTerm = albedo / kPi * reference.sunTransmittance(position, sun) * std::max(glm::dot(normal, sun), 0.0) * double(q.b.w);
        const glm::dvec3 gotSun = glm::dvec3(withSky[i]) - glm::dvec3(skyOnly[i]);
        for (int ch = 0; ch < 3; ++ch) {
            const double error = std::abs(gotSun[ch] - sunTerm[ch]) / std::max(albedo[ch] / kPi, 1e-9);  // per unit of albedo / pi
            largestSun = std::max(largestSun, error);
            EXPECT_LT(error, 0.015) << model << " sun term, point " << i << " channel " << ch << ": " << gotSun[ch] << " against " << sunTerm[ch];
        }
        if (i % 4 != 0) continue;  // the Monte Carlo sky at a quarter of the points
        const auto sky = reference.skyIrradiance(position, sun, 4, 400, 700u + static_cast<unsigned>(i));
        const double occlusion = std::clamp((1.0 + glm::dot(normal, up)) * 0.5, 0.0, 1.0);
        const double scale = std::max({sky.mean.r, sky.mean.g, sky.mean.b, 1e-3});
        double error = 0.0;
        for (int ch = 0; ch < 3; ++ch) {
            const double got = skyOnly[i][ch] / (albedo[ch] / kPi * occlusion);
            error = std::max(error, std::max(0.0, std::abs(got - sky.mean[ch]) - 4.0 * sky.standardError[ch]) / scale);
        }
        skyErrors.push_back(error);
    }
    std::sort(skyErrors.begin(), skyErrors.end());
    const double median = skyErrors[skyErrors.size() / 2], ninetieth = skyErrors[skyErrors.size() * 9 / 10], largest = skyErrors.back();
    std::printf("%s terrain shading: sun term within %.4f of the reference per unit albedo / pi; sky term against Monte Carlo: median "
                "%.4f, 90th percentile %.4f, largest %.4f\n", model, largestSun, median, ninetieth, largest);
    EXPECT_LT(median, 0.03) << model;
    EXPECT_LT(ninetieth, 0.08) << model;
    EXPECT_LT(largest, 0.20) << model;
}

std::vector<ProbeQuery> withVisibility(std::vector<ProbeQuery> queries, float visibility) {
    for (auto& q : queries) q.b.w = visibility;
    return queries;
}

TEST_F(TerrainFunctions, YusovShadingMatchesTheReference) {
    AtmosphereParameters p;
    p.lut = LutDimensions::of(LutResolution::Medium);
    p.scatteringOrders = 4;
    YusovPrecomputation tables(device(), p);
    tables.runAll(context(), *productShaderLibrary);
    ConstantBuffer<gpu::AtmosphereConstants> atmosphere(device());
    atmosphere.update(context(), p.constants());
    const auto sampler = states::linearClamp(device());
    // Yusov's ambient light is the sky's irradiance at the ground whatever the altitude
    // (Yusov 2013 indexes it by the sun's angle alone): points at the ground.
    const auto queries = shadingQueries(240, 0.0, 11);
    const ShaderKey key{"terrain/terrain_probe.hlsl", "shading", "cs_5_0", {"GROUND_LIGHTING=1"}};
    const auto run = [&](const std::vector<ProbeQuery>& q) {
        return runProbe(key, q, {atmosphere.get(), nullptr, nullptr},
                        {nullptr, tables.tables().netDensity.srv.Get(), tables.tables().ambientLight.srv.Get()}, sampler.Get());
    };
    checkShading(queries, run(queries), run(withVisibility(queries, 0.0f)), ReferenceAtmosphere(p), p.earthRadius, "Yusov 2013");
}

TEST_F(TerrainFunctions, BrunetonShadingMatchesTheReference) {
    BrunetonParameters p;
    p.physics.scatteringOrders = 4;
    p.physics.lut = LutDimensions::of(LutResolution::Medium);
    p.lut = atmosphere::bruneton::Dimensions::of(LutResolution::Medium);
    p.groundAlbedo = 0.0;  // the reference's ground is black
    BrunetonPrecomputation tables(device(), p);
    tables.runAll(context(), *productShaderLibrary);
    ConstantBuffer<gpu::AtmosphereConstants> atmosphere(device());
    atmosphere.update(context(), p.physics.constants());
    ConstantBuffer<gpu::BrunetonConstants> bruneton(device());
    bruneton.update(context(), p.constants());
    const auto sampler = states::linearClamp(device());
    const auto queries = shadingQueries(240, 4000.0, 12);  // Bruneton's irradiance follows the altitude
    const ShaderKey key{"terrain/terrain_probe.hlsl", "shading", "cs_5_0", {"GROUND_LIGHTING=2"}};
    const auto run = [&](const std::vector<ProbeQuery>& q) {
        return runProbe(key, q, {atmosphere.get(), bruneton.get(), nullptr},
                        {nullptr, tables.tables().transmittance.srv.Get(), tables.tables().irradiance.srv.Get()}, sampler.Get());
    };
    checkShading(queries, run(queries), run(withVisibility(queries, 0.0f)), ReferenceAtmosphere(p.physics), p.physics.earthRadius,
                 "Bruneton 2008");
}

// Hillaire 2020's tables at the paper's sizes: the sun through his transmittance table, the sky
// through the irradiance table Firmament derives from his model. The model's multiple scattering
// is an approximation (HillaireMultipleScattering.*: 5 to 12% off from the ground), held here to
// the same bounds as the other models' tables.
TEST_F(TerrainFunctions, HillaireShadingMatchesTheReference) {
    HillaireParameters p;
    HillairePrecomputation tables(device(), p);
    tables.runAll(context(), *productShaderLibrary);
    ConstantBuffer<gpu::AtmosphereConstants> atmosphere(device());
    atmosphere.update(context(), p.physics.constants());
    ConstantBuffer<gpu::HillaireConstants> hillaire(device());
    hillaire.update(context(), p.constants());
    const auto sampler = states::linearClamp(device());
    const auto queries = shadingQueries(240, 4000.0, 13);
    const ShaderKey key{"terrain/terrain_probe.hlsl", "shading", "cs_5_0", {"GROUND_LIGHTING=3"}};
    const auto run = [&](const std::vector<ProbeQuery>& q) {
        return runProbe(key, q, {atmosphere.get(), hillaire.get(), nullptr},
                        {nullptr, tables.tables().transmittance.srv.Get(), tables.tables().irradiance.srv.Get()}, sampler.Get());
    };
    checkShading(queries, run(queries), run(withVisibility(queries, 0.0f)), ReferenceAtmosphere(p.physics), p.physics.earthRadius,
                 "Hillaire 2020");
}

}  // namespace
}  // namespace firmament::test
