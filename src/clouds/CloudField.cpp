#include "clouds/CloudField.h"

#include "clouds/CloudSettings.h"
#include "core/IntegerHash.h"

#include <glm/geometric.hpp>

#include <algorithm>
#include <bit>
#include <cmath>

namespace firmament {

namespace {
constexpr double kTwoPi = 6.28318530717958647692;
// The density map's contrast: the noise's values, spread around 0.5, are stretched by it so that
// the Cloudiness control's range covers clear to overcast.
constexpr float kDensityContrast = 2.5f;

float saturate(float x) { return std::clamp(x, 0.0f, 1.0f); }
float lerp(float a, float b, float t) { return a + t * (b - a); }
// Perlin's quintic fade: the noise's interpolation weight, flat at the lattice points.
float fade(float t) { return t * t * t * (t * (t * 6.0f - 15.0f) + 10.0f); }

float latticeValue(std::uint32_t x, std::uint32_t y, std::uint32_t octave) {
    return unitFromHash(hash32(x ^ hash32(y ^ hash32(octave + 0x9e3779b9u))));
}

}  // namespace

unsigned cloudParticleCapacity(const CloudSettings& settings) {
    const long long particles = CloudGrid::cellCount(settings.rings, settings.effectiveRingDimension()) * settings.maxLayers;
    return static_cast<unsigned>(std::min<long long>(particles, kMaxCloudParticles));
}

gpu::CloudFieldConstants cloudFieldConstants(const CloudSettings& settings, glm::dvec3 camera, double seconds) {
    const CloudGrid grid(settings);
    const double outer = grid.cellSize(grid.rings() - 1);
    const long long cx = static_cast<long long>(std::floor(camera.x / outer + 0.5));
    const long long cz = static_cast<long long>(std::floor(camera.z / outer + 0.5));
    gpu::CloudFieldConstants c{};
    c.grid = glm::vec4(static_cast<float>(grid.cellSize(0)), settings.altitude, settings.thickness, settings.particleDistance);
    c.layout = glm::uvec4(static_cast<unsigned>(grid.rings()), static_cast<unsigned>(grid.dimension()), static_cast<unsigned>(settings.maxLayers),
                          static_cast<unsigned>(CloudGrid::cellCount(grid.rings(), grid.dimension())));
    c.centre = glm::uvec4(static_cast<unsigned>(static_cast<int>(cx)), static_cast<unsigned>(static_cast<int>(cz)), cloudParticleCapacity(settings), 0u);
    c.coverage = glm::vec4(settings.cloudiness, static_cast<float>(1.0 / kCoarseDensityPeriod), static_cast<float>(1.0 / kFineDensityPeriod),
                           static_cast<float>(settings.densityResolution));
    // The wind's travel, kept within each tap's period for precision.
    const double travel = kWindPerSpeed * settings.speed * seconds;
    auto within = [](double v, double period) { return static_cast<float>(v - std::floor(v / period) * period); };
    c.wind = glm::vec4(within(travel * kWindDirectionX, kCoarseDensityPeriod), within(travel * kWindDirectionZ, kCoarseDensityPeriod),
                       within(travel * kWindDirectionX, kFineDensityPeriod), within(travel * kWindDirectionZ, kFineDensityPeriod));
    // The particles' pulses: size with a period of 25 s, density of 18 s.
    c.animation = glm::vec4(static_cast<float>(std::fmod(seconds * kTwoPi / 25.0, kTwoPi)), static_cast<float>(std::fmod(seconds * kTwoPi / 18.0, kTwoPi)),
                            0.0f, 0.0f);
    return c;
}

float cloudDensityTexel(int resolution, int x, int y) {
    const int octaves = std::max(static_cast<int>(std::bit_width(static_cast<unsigned>(resolution))) - 1 - 3, 1);
    float sum = 0.0f, total = 0.0f, amplitude = 1.0f;
    for (int o = 0; o < octaves; ++o) {
        const int lattice = 4 << o;
        const float px = (static_cast<float>(x) + 0.5f) * static_cast<float>(lattice) / static_cast<float>(resolution);
        const float py = (static_cast<float>(y) + 0.5f) * static_cast<float>(lattice) / static_cast<float>(resolution);
        const float fx = std::floor(px), fy = std::floor(py);
        const float tx = fade(px - fx), ty = fade(py - fy);
        const std::uint32_t mask = static_cast<std::uint32_t>(lattice) - 1u;
        const std::uint32_t ax = static_cast<std::uint32_t>(fx) & mask, ay = static_cast<std::uint32_t>(fy) & mask;
        const std::uint32_t bx = (ax + 1u) & mask, by = (ay + 1u) & mask;
        const auto octave = static_cast<std::uint32_t>(o);
        const float value = lerp(lerp(latticeValue(ax, ay, octave), latticeValue(bx, ay, octave), tx),
                                 lerp(latticeValue(ax, by, octave), latticeValue(bx, by, octave), tx), ty);
        sum += amplitude * value;
        total += amplitude;
        amplitude *= 0.5f;
    }
    return saturate(0.5f + (sum / total - 0.5f) * kDensityContrast);
}

std::vector<float> cloudDensityMap(int resolution) {
    std::vector<float> map(static_cast<size_t>(resolution) * resolution);
    for (int y = 0; y < resolution; ++y)
        for (int x = 0; x < resolution; ++x) map[static_cast<size_t>(y) * resolution + x] = cloudDensityTexel(resolution, x, y);
    return map;
}

}  // namespace firmament
