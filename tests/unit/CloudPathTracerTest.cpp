// The clouds' path-traced reference on the CPU (src/reference/CloudPathTracer, CloudMedium) against
// what does not share its code: Beer's law through a slab, the closed form of a slab's single
// scattering, a white furnace (albedo 1 in a uniform sky: every path returns the sky exactly),
// the flux through a slab conserved, the scattering table's single scattering quadrature and its
// multiple scattering (the shipped file), and the particle field's grid against a sum over every
// particle.
#include "clouds/LightSpace.h"
#include "clouds/ParticleDensity.h"
#include "clouds/ParticleScattering.h"
#include "reference/CloudMedium.h"
#include "reference/CloudPathTracer.h"
#include "reference/DeckDiffusion.h"
#include "reference/SunColumnTwin.h"
#include "support/TestPaths.h"

#include <gtest/gtest.h>

#include <glm/geometric.hpp>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <random>

namespace firmament {
namespace {

constexpr double kPi = 3.14159265358979323846;

glm::dvec3 uniformSky(glm::dvec3) { return glm::dvec3(1.0); }

// Binomial or sample standard error of a mean of n values with mean m, each 0 or 1.
double binomialError(double m, int n) { return std::sqrt(std::max(m * (1.0 - m), 1e-12) / n); }

TEST(CloudPathTracer, UnscatteredLightThroughASlabFollowsBeersLaw) {
    const HomogeneousSlab slab(0.0, 100.0, 0.02);  // optical thickness 2
    CloudPathSettings settings;
    settings.lastOrder = 0;
    CloudLighting lighting;
    lighting.sky = uniformSky;
    const CloudPathTracer tracer(slab, lighting, settings);
    std::mt19937_64 random(3);
    for (double mu : {1.0, 0.5}) {
        const MediumRay up{{0.0, -50.0, 0.0}, glm::normalize(glm::dvec3(std::sqrt(1.0 - mu * mu), mu, 0.0))};
        const int paths = 40000;
        const double got = tracer.meanRadiance(up, paths, random).x, expected = std::exp(-2.0 / mu);
        EXPECT_NEAR(got, expected, 4.0 * binomialError(expected, paths)) << "mu " << mu;
        // Ratio tracking estimates the same transmittance.
        double ratio = 0.0;
        for (int k = 0; k < paths; ++k) ratio += tracer.transmittance(up, 1e9, random);
        EXPECT_NEAR(ratio / paths, expected, 4.0 * binomialError(expected, paths)) << "mu " << mu;
    }
}

// Single scattering leaving the top of a slab of optical thickness tau, sun at cosine mu0, viewer
// at cosine mu, albedo w:  L = E w p(theta) mu0 / (mu0 + mu) (1 - e^(-tau (1/mu0 + 1/mu))).
TEST(CloudPathTracer, SingleScatteringFromASlabIsTheClosedForm) {
    const double thickness = 100.0, extinction = 0.01, tau = thickness * extinction;
    const HomogeneousSlab slab(0.0, thickness, extinction);
    for (double g : {0.0, 0.9}) {
        CloudPathSettings settings;
        settings.asymmetry = g;
        settings.firstOrder = settings.lastOrder = 1;
        settings.albedo = 0.9;
        CloudLighting lighting;
        const double mu0 = 0.8, mu = 0.6;
        lighting.toSun = glm::dvec3(0.6, mu0, 0.0);
        lighting.sunIrradiance = glm::dvec3(2.0);
        const CloudPathTracer tracer(slab, lighting, settings);
        std::mt19937_64 random(11);
        // Looking down at cosine mu, the light leaving upward toward the camera.
        for (double side : {-1.0, 1.0}) {
            const glm::dvec3 down(side * 0.8, -mu, 0.0);
            const double cosine = glm::dot(lighting.toSun, down);
            const double expected = 2.0 * settings.albedo * henyeyGreensteinPhase(cosine, g) * mu0 / (mu0 + mu) * (1.0 - std::exp(-tau * (1.0 / mu0 + 1.0 / mu)));
            const int paths = 60000;
            const double got = tracer.meanRadiance({{0.0, 300.0, 0.0}, down}, paths, random).x;
            std::printf("g %.1f, scattering cosine %+.2f: single scattering %.6f, closed form %.6f\n", g, cosine, got, expected);
            EXPECT_NEAR(got / expected, 1.0, 0.02) << "g " << g << " cosine " << cosine;
        }
    }
}

// A white furnace: in a uniform sky of radiance 1, a medium that absorbs nothing can only pass the
// sky on, so every path's estimate is exactly 1, however often it scatters (a lost or an invented
// path would show); with albedo 0.7 the medium darkens it.
TEST(CloudPathTracer, AWhiteFurnaceReturnsTheSkyThroughEveryMedium) {
    std::mt19937_64 random(5);
    std::vector<ModelParticle> particles;
    std::uniform_real_distribution<float> unit(0.0f, 1.0f);
    for (int k = 0; k < 60; ++k) {
        ModelParticle q;
        q.centre = glm::vec3(4000.0f * unit(random) - 2000.0f, 3000.0f + 600.0f * unit(random), 4000.0f * unit(random) - 2000.0f);
        q.horizontalRadius = 300.0f + 500.0f * unit(random);
        q.verticalRadius = 200.0f + 200.0f * unit(random);
        q.density = 0.3f + 0.7f * unit(random);
        q.azimuth = 6.28f * unit(random);
        particles.push_back(q);
    }
    const ParticleMedium field(particles, 6360000.0, ParticleDensityMethod::RadialNoise, kCloudExtinction);
    const HomogeneousSphere sphere(glm::dvec3(0.0), 200.0, kCloudExtinction);
    const HomogeneousSlab slab(0.0, 700.0, kCloudExtinction);
    struct Case {
        const CloudMedium* medium;
        MediumRay ray;
        const char* name;
    } cases[] = {{&field, {{0.0, 1000.0, 0.0}, glm::normalize(glm::dvec3(0.1, 1.0, 0.05))}, "particle field"},
                 {&sphere, {{0.0, 0.0, -500.0}, {0.0, 0.0, 1.0}}, "sphere"},
                 {&slab, {{0.0, 1000.0, 0.0}, {0.0, -1.0, 0.0}}, "slab of optical thickness 49"}};
    for (const Case& c : cases) {
        CloudPathSettings settings;
        CloudLighting lighting;
        lighting.sky = uniformSky;
        lighting.sunIrradiance = glm::dvec3(0.0);
        const CloudPathTracer tracer(*c.medium, lighting, settings);
        double least = 1e9, most = -1e9;
        long events = 0;
        const int paths = 400;
        for (int k = 0; k < paths; ++k) {
            int scatterings = 0;
            const double value = tracer.radiance(c.ray, random, &scatterings).x;
            least = std::min(least, value);
            most = std::max(most, value);
            events += scatterings;
        }
        std::printf("%s: %.1f scattering events a path\n", c.name, static_cast<double>(events) / paths);
        EXPECT_GT(events, paths) << c.name << ": the paths must scatter for the test to mean anything";
        EXPECT_NEAR(least, 1.0, 1e-12) << c.name;
        EXPECT_NEAR(most, 1.0, 1e-12) << c.name;

        settings.albedo = 0.7;
        const CloudPathTracer absorbing(*c.medium, lighting, settings);
        EXPECT_LT(absorbing.meanRadiance(c.ray, paths, random).x, 0.95) << c.name;
    }
}

// The sun's flux into a slab that absorbs nothing leaves it all: reflected, transmitted after
// scattering, and the unscattered beam e^(-tau / mu0). The fluxes are the radiance's cosine-
// weighted integrals over each hemisphere (pi times the mean over cosine-distributed directions).
TEST(CloudPathTracer, TheSunsFluxThroughASlabIsConserved) {
    const double thickness = 100.0, extinction = 0.01;  // optical thickness 1
    const HomogeneousSlab slab(0.0, thickness, extinction);
    CloudPathSettings settings;
    settings.firstOrder = 1;
    CloudLighting lighting;
    const double mu0 = 0.8;
    lighting.toSun = glm::dvec3(0.6, mu0, 0.0);
    const CloudPathTracer tracer(slab, lighting, settings);
    std::mt19937_64 random(9);
    std::uniform_real_distribution<double> unit(0.0, 1.0);
    const int paths = 200000;
    double reflected = 0.0, transmitted = 0.0;
    for (int k = 0; k < paths; ++k) {
        const double u = unit(random), phi = 2.0 * kPi * unit(random), cosine = std::sqrt(1.0 - u), sine = std::sqrt(u);
        const glm::dvec3 up(sine * std::cos(phi), cosine, sine * std::sin(phi));
        reflected += tracer.radiance({{0.0, thickness + 10.0, 0.0}, -up}, random).x;
        transmitted += tracer.radiance({{0.0, -10.0, 0.0}, up}, random).x;
    }
    reflected *= kPi / paths;
    transmitted *= kPi / paths;
    const double beam = mu0 * std::exp(-extinction * thickness / mu0);
    std::printf("flux in %.4f: reflected %.4f, transmitted diffusely %.4f, the beam %.4f, sum %.4f\n", mu0, reflected, transmitted, beam,
                reflected + transmitted + beam);
    EXPECT_NEAR((reflected + transmitted + beam) / mu0, 1.0, 0.01);
    EXPECT_GT(reflected, 0.02);
    EXPECT_GT(transmitted, 0.1);
}

// The light of a slab (of unit height, at y 0 to 1, the sun overhead): the fluxes reflected and
// transmitted (pi times the mean radiance over cosine-weighted directions) and the radiance
// straight back towards the sun at the top, straight on at the bottom, and at the bottom 37
// degrees off the sun's rays (cosine 0.8: the view from below of the golden view clouds-midday).
struct SlabLight {
    double reflected = 0.0, transmitted = 0.0, back = 0.0, on = 0.0, slanted = 0.0;
};

SlabLight pathTracedSlab(const CloudPathTracer& tracer, int paths, std::mt19937_64& random) {
    std::uniform_real_distribution<double> unit(0.0, 1.0);
    SlabLight light;
    for (int k = 0; k < paths; ++k) {
        const double u = unit(random), phi = 2.0 * kPi * unit(random), cosine = std::sqrt(1.0 - u), sine = std::sqrt(u);
        const glm::dvec3 up(sine * std::cos(phi), cosine, sine * std::sin(phi));
        light.reflected += tracer.radiance({{0.0, 1.1, 0.0}, -up}, random).x;
        light.transmitted += tracer.radiance({{0.0, -0.1, 0.0}, up}, random).x;
    }
    light.reflected *= kPi / paths;
    light.transmitted *= kPi / paths;
    light.back = tracer.meanRadiance({{0.0, 1.1, 0.0}, {0.0, -1.0, 0.0}}, paths, random).x;
    light.on = tracer.meanRadiance({{0.0, -0.1, 0.0}, {0.0, 1.0, 0.0}}, paths, random).x;
    light.slanted = tracer.meanRadiance({{0.0, -0.1, 0.0}, {0.6, 0.8, 0.0}}, paths, random).x;
    return light;
}

// The same of a model's radiance(depth, cosine to the sun's travel) in a slab of thickness tau:
// the fluxes 2 pi times the cosine-weighted integral over each face's hemisphere.
template <typename Radiance>
SlabLight modelSlab(const Radiance& radiance, double tau) {
    SlabLight light;
    const int n = 200;
    for (int k = 0; k < n; ++k) {
        const double m = (k + 0.5) / n;
        light.reflected += radiance(0.0, -m) * m * 2.0 * kPi / n;
        light.transmitted += radiance(tau, m) * m * 2.0 * kPi / n;
    }
    light.back = radiance(0.0, -1.0);
    light.on = radiance(tau, 1.0);
    light.slanted = radiance(tau, 0.8);
    return light;
}

// Deck diffusion (src/reference/DeckDiffusion.h), the particle renderer's model of the light that
// diffuses through a column of cloud, against the path tracer in a homogeneous slab lit along its
// normal, g = 0.9, at optical thicknesses 4, 16 and 48: the fluxes reflected and transmitted
// after scattering (the model's diffuse radiance integrated over each face's hemisphere; the
// transmitted flux also holds the forward peak's light, e^(-(1 - g^2) tau) - e^(-tau), which the
// model counts with the direct beam), and the radiance straight back towards the sun at the top
// and straight on at the bottom.
TEST(CloudPathTracer, DeckDiffusionMatchesThePathTracedSlab) {
    const double g = 0.9, f = g * g;
    CloudLighting lighting;
    lighting.toSun = glm::dvec3(0.0, 1.0, 0.0);
    std::mt19937_64 random(31);
    for (const double tau : {4.0, 16.0, 48.0}) {
        const HomogeneousSlab slab(0.0, 1.0, tau);
        const CloudPathTracer tracer(slab, lighting, CloudPathSettings{});
        const SlabLight traced = pathTracedSlab(tracer, 20000, random);
        SlabLight model = modelSlab([&](double depth, double mu) { return deckDiffuseRadiance(depth, tau, mu, g); }, tau);
        model.transmitted += std::exp(-(1.0 - f) * tau) - std::exp(-tau);
        std::printf("optical thickness %.0f: reflected %.4f (model %.4f), transmitted after scattering %.4f (model %.4f); radiance back %.4f "
                    "(model %.4f), on %.4f (model %.4f)\n",
                    tau, traced.reflected, model.reflected, traced.transmitted, model.transmitted, traced.back, model.back, traced.on, model.on);
        // Measured (20,000 paths): the fluxes within 4% at every thickness in the MinGW build's
        // random stream, but the transmitted flux at 48 15% off in the portable build's (the
        // paths through 48 are long and few carry the light: that much is Monte Carlo noise);
        // Eddington's linear radiance too bright straight back (+124%, +34%, +13%) and too dim
        // straight on at 16 and 48 (-16%, -8%; at 4 the path tracer's straight-on light is
        // mostly the forward peak). C1's 5 made 4 puts the fluxes 75% to 150% off.
        EXPECT_NEAR(model.reflected / traced.reflected, 1.0, 0.2) << tau;
        EXPECT_NEAR(model.transmitted / traced.transmitted, 1.0, 0.2) << tau;
        if (tau >= 16.0) {
            EXPECT_NEAR(model.back / traced.back, 1.0, 0.45) << tau;
            EXPECT_NEAR(model.on / traced.on, 1.0, 0.3) << tau;
        }
    }
}

// Deck diffusion's solved slab (src/reference/DeckDiffusion.h: the shipped table, looked up as the
// shader does), the light scattered more than once in a column of cloud, against the path
// tracer's orders from the second on in the same medium: a homogeneous slab lit along its normal,
// of optical thickness 4, 16 and 48, of droplets of g = 0.9 (the table's own medium, not delta-M
// scaled). Compared: the fluxes reflected and transmitted (the look-up integrated over each
// face's hemisphere), and the radiance straight back towards the sun at the top and 37 degrees
// off the sun's rays at the bottom; straight on at the bottom is printed, not held: there the
// table's solver smooths the forward peak at its 32 streams (measured 11% low at 4, 4% at 16).
// The table's solver is exact up to its streams (SlabDoublingTest); what this adds is an
// independent method for the same light.
TEST(CloudPathTracer, TheSolvedSlabMatchesThePathTracedSlab) {
    const DeckDiffusionTable table = readDeckDiffusion(test::executableFolder() / "media" / "clouds" / "deck-diffusion.exr", DeckDiffusionParameters{});
    CloudLighting lighting;
    lighting.toSun = glm::dvec3(0.0, 1.0, 0.0);
    CloudPathSettings settings;
    settings.firstOrder = 2;
    settings.asymmetry = 0.9;
    std::mt19937_64 random(31);
    for (const double tau : {4.0, 16.0, 48.0}) {
        const HomogeneousSlab slab(0.0, 1.0, tau);
        const CloudPathTracer tracer(slab, lighting, settings);
        const SlabLight traced = pathTracedSlab(tracer, 20000, random);
        const SlabLight model = modelSlab([&](double depth, double mu) { return solvedSlabMultipleScattering(table, depth, tau, mu); }, tau);
        std::printf("optical thickness %.0f, scattered twice or more: reflected %.4f (model %.4f), transmitted %.4f (model %.4f); radiance back %.4f "
                    "(model %.4f), 37 degrees on %.4f (model %.4f), straight on %.4f (model %.4f)\n",
                    tau, traced.reflected, model.reflected, traced.transmitted, model.transmitted, traced.back, model.back, traced.slanted, model.slanted,
                    traced.on, model.on);
        // Measured (20,000 paths, 2026-12-07, the portable build's random stream): every number
        // within 7% (the worst, reflected at 4, 6.5% low), 37 degrees on within 3%; a stream
        // that differed only in its order of draws put back at 16 8% high: the Monte Carlo noise
        // of so few paths through a medium this forward-scattering.
        EXPECT_NEAR(model.reflected / traced.reflected, 1.0, 0.12) << tau;
        EXPECT_NEAR(model.transmitted / traced.transmitted, 1.0, 0.12) << tau;
        EXPECT_NEAR(model.back / traced.back, 1.0, 0.12) << tau;
        EXPECT_NEAR(model.slanted / traced.slanted, 1.0, 0.12) << tau;
    }
}

// The reference sphere of the scattering table (radius 1, optical radius 14, g 0.9): single
// scattering along texel rays against the generator's quadrature times the phase function.
TEST(CloudPathTracer, TheSpheresSingleScatteringIsTheTablesQuadrature) {
    const ParticleScatteringParameters p = ParticleScatteringParameters::sphere(14.0);
    const HomogeneousSphere sphere(glm::dvec3(0.0), 1.0, p.opticalRadius(0));
    CloudPathSettings settings;
    settings.firstOrder = settings.lastOrder = 1;
    CloudLighting lighting;
    lighting.toSun = glm::dvec3(0.0, 0.0, 1.0);
    const CloudPathTracer tracer(sphere, lighting, settings);
    std::mt19937_64 random(13);
    for (const glm::ivec3 texel : {glm::ivec3(2, 10, 3), glm::ivec3(10, 40, 8), glm::ivec3(16, 5, 12), glm::ivec3(24, 20, 2), glm::ivec3(30, 50, 14)}) {
        const SurfaceRay ray = scatteringTexelRay(p, texel.x, texel.y, texel.z);
        const double phase = henyeyGreensteinPhase(glm::dot(lighting.toSun, ray.direction), p.asymmetry);
        const double expected = singleScatteringQuadrature(p.opticalRadius(0), ray, 4096) * phase;
        const double got = tracer.meanRadiance({ray.entry - ray.direction * 0.01, ray.direction}, 40000, random).x;
        std::printf("texel (%d, %d, %d): single scattering %.5g, quadrature %.5g\n", texel.x, texel.y, texel.z, got, expected);
        EXPECT_NEAR(got, expected, 0.03 * expected + 1e-6) << texel.x << ", " << texel.y << ", " << texel.z;
    }
}

// Multiple scattering against the table's generator, in the medium the generator solves: its
// orders run in the delta-M scaled sphere (the layer of optical radius 16: 16 (1 - g^2) = 3.04,
// asymmetry (g - g^2) / (1 - g^2) = 0.47) until they converge, so the path tracer traces that
// sphere and counts every order from 2. Then the same texels in the true sphere (optical radius
// 16, g = 0.9, every order from 2), which is the light the table stands for in the renderer:
// printed, a measurement for docs/clouds.md.
TEST(CloudPathTracer, TheSpheresMultipleScatteringMatchesTheTablesGenerator) {
    const ParticleScatteringParameters p;
    const ParticleScatteringTable table = readParticleScattering(test::executableFolder() / "media" / "clouds" / "particle-scattering.exr", p);
    const int layer = 6;
    const double f = p.asymmetry * p.asymmetry, tau = p.opticalRadius(layer);
    ASSERT_DOUBLE_EQ(tau, 16.0);
    const HomogeneousSphere scaled(glm::dvec3(0.0), 1.0, tau * (1.0 - f)), truth(glm::dvec3(0.0), 1.0, tau);
    CloudPathSettings scaledSettings, trueSettings;
    scaledSettings.firstOrder = trueSettings.firstOrder = 2;
    scaledSettings.asymmetry = (p.asymmetry - f) / (1.0 - f);
    CloudLighting lighting;
    lighting.toSun = glm::dvec3(0.0, 0.0, 1.0);
    const CloudPathTracer scaledTracer(scaled, lighting, scaledSettings), trueTracer(truth, lighting, trueSettings);
    std::mt19937_64 random(17);
    double sumScaled = 0.0, sumTrue = 0.0, sumTable = 0.0, worst = 0.0;
    for (const glm::ivec3 texel : {glm::ivec3(2, 10, 3), glm::ivec3(10, 40, 8), glm::ivec3(16, 5, 12), glm::ivec3(24, 20, 2), glm::ivec3(30, 50, 14),
                                   glm::ivec3(20, 33, 6)}) {
        const SurfaceRay ray = scatteringTexelRay(p, texel.x, texel.y, texel.z);
        const MediumRay view{ray.entry - ray.direction * 0.01, ray.direction};
        const double expected = table.multiple[table.index(texel.x, texel.y, texel.z, layer)];
        const double inScaled = scaledTracer.meanRadiance(view, 60000, random).x, inTruth = trueTracer.meanRadiance(view, 30000, random).x;
        std::printf("texel (%d, %d, %d): table %.5g; path traced in the scaled sphere %.5g (table / it %.3f), in the true sphere %.5g (%.3f)\n", texel.x,
                    texel.y, texel.z, expected, inScaled, expected / inScaled, inTruth, expected / inTruth);
        sumScaled += inScaled;
        sumTrue += inTruth;
        sumTable += expected;
        worst = std::max(worst, std::abs(expected / inScaled - 1.0));
    }
    std::printf("over the texels, table / path traced: %.3f in the scaled sphere (worst texel %.3f off), %.3f in the true sphere\n", sumTable / sumScaled,
                worst, sumTable / sumTrue);
    EXPECT_NEAR(sumTable / sumScaled, 1.0, 0.05);
    EXPECT_LT(worst, 0.15);
}

// The table's light at a texel ray for a sphere of optical radius tau, as the shader looks it up
// (clouds/particle_lighting.hlsli): linear in log2 of the optical radius between the two layers
// around it, clamped to the thinnest and the thickest.
glm::dvec3 layeredTexel(const ParticleScatteringTable& table, glm::ivec3 texel, double tau) {
    const ParticleScatteringParameters& p = table.parameters;
    const double layer = std::clamp(std::log2(tau / p.firstOpticalRadius), 0.0, p.opticalRadii - 1.0);
    const int layer0 = std::min(static_cast<int>(layer), p.opticalRadii - 2);
    const double w = layer - layer0;
    const size_t a = table.index(texel.x, texel.y, texel.z, layer0), b = table.index(texel.x, texel.y, texel.z, layer0 + 1);
    const auto lerp = [&](const std::vector<float>& v) { return v[a] + w * (v[b] - v[a]); };
    return {lerp(table.single), lerp(table.multiple), lerp(table.peak)};
}

// An isolated particle as the particle renderer shades it (shaders/clouds/shade_particles.hlsl,
// without the atmosphere and the sky), with Multiple scattering: Particle table (and beside it
// the default, Deck diffusion, solved slab): the table's layers at the particle's optical
// radius, at the view ray's entry point and direction: single scattering times the droplets' phase function,
// the forward peak's light times the scaled medium's, plus multiple scattering, per unit opacity
// of the sphere's chord, times the particle's opacity
// 1 - e^(-tau) along the ray (the same, for a homogeneous sphere); against the path-traced light
// of the same sphere (every order), at optical radii 14, 4.2 and 0.98, none of them a layer's.
// Before the table had layers (one sphere of optical radius 14 for every particle) and the
// forward peak's light, this was 0.82, 0.56 and 0.91 over the first five texels alone.
TEST(CloudPathTracer, AShadedParticleAgainstThePathTracedSphereAtThreeOpticalRadii) {
    const ParticleScatteringParameters p;
    const ParticleScatteringTable table = readParticleScattering(test::executableFolder() / "media" / "clouds" / "particle-scattering.exr", p);
    CloudLighting lighting;
    lighting.toSun = glm::dvec3(0.0, 0.0, 1.0);
    std::mt19937_64 random(29);
    // Five texels the light leaves in every direction, and five near the sun's direction (within
    // 18 degrees of it), where the droplets' forward peak is.
    const glm::ivec3 texels[] = {glm::ivec3(2, 10, 3),  glm::ivec3(10, 40, 8), glm::ivec3(16, 5, 12), glm::ivec3(24, 20, 2), glm::ivec3(20, 33, 6),
                                 glm::ivec3(31, 10, 0), glm::ivec3(29, 40, 1), glm::ivec3(27, 32, 2), glm::ivec3(30, 20, 3), glm::ivec3(28, 33, 0)};
    const double scaledG = p.asymmetry / (1.0 + p.asymmetry);
    const DeckDiffusionTable deck = readDeckDiffusion(test::executableFolder() / "media" / "clouds" / "deck-diffusion.exr", DeckDiffusionParameters{});
    for (const double tau : {14.0, 4.2, 0.98}) {
        const HomogeneousSphere sphere(glm::dvec3(0.0), 1.0, tau);
        const CloudPathTracer tracer(sphere, lighting, CloudPathSettings{});
        double sumRenderer = 0.0, sumSlab = 0.0, sumTraced = 0.0;
        for (const glm::ivec3 texel : texels) {
            const SurfaceRay ray = scatteringTexelRay(p, texel.x, texel.y, texel.z);
            const glm::dvec3 light = layeredTexel(table, texel, tau);
            const double cosine = glm::dot(lighting.toSun, ray.direction);
            const double renderer = light.x * henyeyGreensteinPhase(cosine, p.asymmetry) + light.z * henyeyGreensteinPhase(cosine, scaledG) + light.y;
            // The default shading (Deck diffusion, solved slab) of a particle alone: single
            // scattering with the droplets' phase function, and the slab of its own chord along
            // the sun (2 tau) at its face toward the camera, times the opacity of the ray's chord.
            const double opacity = 1.0 - std::exp(-2.0 * tau * std::max(glm::dot(-ray.entry, ray.direction), 0.0));
            const double slab = light.x * henyeyGreensteinPhase(cosine, p.asymmetry) +
                                opacity * solvedSlabMultipleScattering(deck, tau * (1.0 + cosine), 2.0 * tau, cosine);
            const double traced = tracer.meanRadiance({ray.entry - ray.direction * 0.01, ray.direction}, 20000, random).x;
            sumRenderer += renderer;
            sumSlab += slab;
            sumTraced += traced;
        }
        std::printf("optical radius %.2f: the particle renderer / the path-traced sphere over %zu texels: %.3f (Particle table), %.3f (the "
                    "default, Deck diffusion, solved slab)\n",
                    tau, std::size(texels), sumRenderer / sumTraced, sumSlab / sumTraced);
        // Particle table's, measured 1.08, 0.53 and 0.54. Near the sun's direction the thinner
        // spheres get half their light: light scattered into the forward peak and once more is
        // given the scaled medium's broad phase function, where the path tracer keeps some of the
        // peak. (The scaled first order with the droplets' sharp phase function instead, Nakajima
        // and Tanaka's correction, gave 9 to 28 times the light at the texels nearest the sun.)
        EXPECT_GT(sumRenderer / sumTraced, 0.45) << "optical radius " << tau;
        EXPECT_LT(sumRenderer / sumTraced, 1.25) << "optical radius " << tau;
        // The default's, measured 2.50, 1.27 and 0.92 (the portable build's random stream: 2.40,
        // 1.26, 0.91): a particle alone is no slab along the sun; its light leaves through its
        // sides, the more the thicker it is (docs/clouds.md, "Deck diffusion": the isolated
        // sphere). In a cloud a particle is one of many and its deck is the column's; held here
        // so that a change to either model shows.
        EXPECT_GT(sumSlab / sumTraced, 0.6) << "optical radius " << tau;
        EXPECT_LT(sumSlab / sumTraced, 3.0) << "optical radius " << tau;
    }
}

// The particles' summed extinction at a point, written out here apart from CloudMedium: each
// particle's frame as shaders/clouds/particle_shape.hlsli builds it, its noise turned by its
// azimuth as the optical depth table's look-up turns it.
double summedExtinction(const std::vector<ModelParticle>& particles, glm::dvec3 point, double earth, ParticleDensityMethod method) {
    double sum = 0.0;
    for (const ModelParticle& q : particles) {
        const glm::dvec3 centre(q.centre);
        const glm::dvec3 normal = glm::normalize(centre + glm::dvec3(0.0, earth, 0.0));
        const glm::dvec3 tangent = glm::normalize(glm::cross(normal, glm::dvec3(0.0, 0.0, 1.0))), bitangent = glm::cross(tangent, normal);
        const glm::dvec3 d = point - centre;
        const glm::dvec3 unit(glm::dot(d, tangent) / q.horizontalRadius, glm::dot(d, normal) / q.verticalRadius, glm::dot(d, bitangent) / q.horizontalRadius);
        const double phi = std::atan2(unit.z, unit.x) + q.azimuth, across = std::hypot(unit.x, unit.z);
        sum += q.density * kCloudExtinction * particleDensity(glm::vec3(glm::dvec3(across * std::cos(phi), unit.y, across * std::sin(phi))), method);
    }
    return sum;
}

// The particle field's grid: along random rays, the extinction through the grid equals the sum
// over every particle, and every point with medium lies in a visited stretch whose majorant
// bounds it.
TEST(CloudPathTracer, TheParticleGridFindsEveryParticleAndItsMajorantsBoundTheExtinction) {
    std::mt19937_64 random(21);
    std::uniform_real_distribution<float> unit(0.0f, 1.0f);
    std::vector<ModelParticle> particles;
    for (int k = 0; k < 200; ++k) {
        ModelParticle q;
        q.centre = glm::vec3(20000.0f * unit(random) - 10000.0f, 2800.0f + 400.0f * unit(random), 20000.0f * unit(random) - 10000.0f);
        q.horizontalRadius = 150.0f + 1500.0f * unit(random);
        q.verticalRadius = 100.0f + 900.0f * unit(random);  // often taller than wide
        q.density = unit(random);
        q.azimuth = 6.28f * unit(random);
        particles.push_back(q);
    }
    const double earth = 6360000.0;
    for (ParticleDensityMethod method : {ParticleDensityMethod::RadialNoise, ParticleDensityMethod::Pyroclastic}) {
        const ParticleMedium field(particles, earth, method, kCloudExtinction);
        EXPECT_GT(field.cells().x * field.cells().y * field.cells().z, 100);
        int inside = 0;
        for (int r = 0; r < 24; ++r) {
            const glm::dvec3 origin(24000.0 * unit(random) - 12000.0, 3000.0 + 2000.0 * (unit(random) - 0.5), 24000.0 * unit(random) - 12000.0);
            const glm::dvec3 direction = glm::normalize(glm::dvec3(unit(random) - 0.5, 0.2 * (unit(random) - 0.5), unit(random) - 0.5));
            const MediumRay ray{origin, direction};
            std::vector<glm::dvec3> stretches;  // t0, t1, majorant
            field.majorants(ray, 30000.0, [&](double t0, double t1, double m) {
                stretches.emplace_back(t0, t1, m);
                return true;
            });
            for (size_t s = 1; s < stretches.size(); ++s) ASSERT_GE(stretches[s].x, stretches[s - 1].y - 1e-6) << "stretches in order";
            for (int k = 0; k < 2000; ++k) {
                const double t = 30000.0 * (k + 0.5) / 2000.0;
                const glm::dvec3 point = origin + direction * t;
                const double sum = summedExtinction(particles, point, earth, method);
                ASSERT_NEAR(field.extinction(point), sum, 1e-9 + 1e-5 * sum) << "ray " << r << " t " << t;
                if (sum <= 0.0) continue;
                ++inside;
                const auto stretch = std::find_if(stretches.begin(), stretches.end(), [&](const glm::dvec3& s) { return t >= s.x && t <= s.y; });
                ASSERT_NE(stretch, stretches.end()) << "ray " << r << " t " << t << ": medium outside every stretch";
                ASSERT_GE(stretch->z, sum - 1e-9) << "ray " << r << " t " << t;
            }
        }
        EXPECT_GT(inside, 500) << "the rays must cross the particles for the test to mean anything";
        // Points all over every particle's ellipsoid, its edges and poles included.
        for (size_t k = 0; k < particles.size(); ++k) {
            const glm::dvec3 centre(particles[k].centre);
            const glm::dvec3 normal = glm::normalize(centre + glm::dvec3(0.0, earth, 0.0));
            const glm::dvec3 tangent = glm::normalize(glm::cross(normal, glm::dvec3(0.0, 0.0, 1.0))), bitangent = glm::cross(tangent, normal);
            for (int n = 0; n < 50; ++n) {
                glm::dvec3 u(unit(random) * 2.0 - 1.0, unit(random) * 2.0 - 1.0, unit(random) * 2.0 - 1.0);
                u *= std::cbrt(unit(random)) / std::max(glm::length(u), 1e-9);
                const glm::dvec3 point = centre + u.x * particles[k].horizontalRadius * tangent + u.y * particles[k].verticalRadius * normal +
                                         u.z * particles[k].horizontalRadius * bitangent;
                const double sum = summedExtinction(particles, point, earth, method);
                ASSERT_NEAR(field.extinction(point), sum, 1e-9 + 1e-5 * sum) << "particle " << k;
            }
        }
    }
}

}  // namespace
}  // namespace firmament
