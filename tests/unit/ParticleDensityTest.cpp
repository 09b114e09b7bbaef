// The cloud particle's density and its optical depth table's parameterization on the CPU
// (src/clouds/ParticleDensity.h, OpticalDepthTable.h): the density methods' shapes, the
// coordinates' round trip, and the chord march's convergence at the table's step count.
#include "clouds/OpticalDepthTable.h"
#include "clouds/ParticleDensity.h"

#include <gtest/gtest.h>

#include <glm/geometric.hpp>

#include <cmath>
#include <random>

namespace firmament {
namespace {

constexpr ParticleDensityMethod kMethods[] = {ParticleDensityMethod::RadialNoise, ParticleDensityMethod::ThresholdedNoise,
                                              ParticleDensityMethod::Pyroclastic};

// A point uniformly distributed in the shell r0 <= |p| < r1.
glm::vec3 pointInShell(std::mt19937& random, float r0, float r1) {
    std::uniform_real_distribution<float> unit(-1.0f, 1.0f), radius(r0, r1);
    glm::vec3 d;
    do d = glm::vec3(unit(random), unit(random), unit(random));
    while (glm::length(d) > 1.0f || glm::length(d) < 1e-3f);
    return glm::normalize(d) * radius(random);
}

double meanDensityInShell(ParticleDensityMethod method, float r0, float r1) {
    std::mt19937 random(11);
    double sum = 0.0;
    for (int k = 0; k < 4000; ++k) sum += particleDensity(pointInShell(random, r0, r1), method);
    return sum / 4000.0;
}

TEST(ParticleDensity, EveryMethodIsDenseInsideAndFadesToNothingAtTheSurface) {
    for (ParticleDensityMethod method : kMethods) {
        const double core = meanDensityInShell(method, 0.0f, 0.3f), rim = meanDensityInShell(method, 0.95f, 1.0f);
        EXPECT_GT(core, 0.8) << static_cast<int>(method);
        EXPECT_LT(rim, 0.15) << static_cast<int>(method);
        EXPECT_EQ(particleDensity(glm::vec3(0.0f, 1.01f, 0.0f), method), 0.0f);
        // Between them the shells' density falls off outwards.
        double previous = 2.0;
        for (float r = 0.0f; r < 1.0f; r += 0.25f) {
            const double shell = meanDensityInShell(method, r, r + 0.25f);
            EXPECT_LT(shell, previous + 0.02) << static_cast<int>(method) << " at " << r;
            previous = shell;
        }
    }
    // The thresholded methods are 0 or 1; the noise makes every method vary within a shell.
    std::mt19937 random(3);
    for (int k = 0; k < 500; ++k) {
        const glm::vec3 p = pointInShell(random, 0.0f, 1.0f);
        const float t = particleDensity(p, ParticleDensityMethod::ThresholdedNoise), y = particleDensity(p, ParticleDensityMethod::Pyroclastic);
        ASSERT_TRUE(t == 0.0f || t == 1.0f);
        ASSERT_TRUE(y == 0.0f || y == 1.0f);
    }
}

TEST(OpticalDepthTable, CoordinatesAndRaysRoundTrip) {
    std::mt19937 random(5);
    std::uniform_real_distribution<float> zenith(0.02f, 0.98f), any(0.0f, 1.0f);
    for (int k = 0; k < 1000; ++k) {
        const glm::vec4 u(zenith(random), any(random), zenith(random), any(random));
        const TableRay ray = opticalDepthRay(u);
        EXPECT_NEAR(glm::length(ray.entry), 1.0f, 1e-5f);
        EXPECT_NEAR(glm::length(ray.direction), 1.0f, 1e-5f);
        EXPECT_GE(glm::dot(-ray.entry, ray.direction), -1e-6f) << "the ray points into the sphere";
        const glm::vec4 back = opticalDepthCoordinates(ray.entry, ray.direction);
        EXPECT_NEAR(back.x, u.x, 1e-4f);
        EXPECT_NEAR(back.z, u.z, 1e-4f);
        // Azimuths wrap.
        EXPECT_NEAR(std::remainder(back.y - u.y, 1.0f), 0.0f, 1e-4f);
        EXPECT_NEAR(std::remainder(back.w - u.w, 1.0f), 0.0f, 1e-4f);
    }
}

TEST(OpticalDepthTable, TheTablesStepCountIsWithinAHundredthOfAConvergedMarch) {
    const OpticalDepthTableSize size;
    std::mt19937 random(9);
    std::uniform_real_distribution<float> any(0.0f, 1.0f);
    double sum = 0.0;
    for (int k = 0; k < 200; ++k) {
        const TableRay ray = opticalDepthRay(glm::vec4(any(random), any(random), any(random), any(random)));
        sum += std::abs(meanChordDensity(ray, size.steps, ParticleDensityMethod::RadialNoise) - meanChordDensity(ray, 1024, ParticleDensityMethod::RadialNoise));
    }
    EXPECT_LT(sum / 200.0, 0.01);
}

}  // namespace
}  // namespace firmament
