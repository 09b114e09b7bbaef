#include "clouds/ParticleDensity.h"

#include "core/IntegerHash.h"

#include <glm/geometric.hpp>

#include <algorithm>
#include <cmath>
#include <cstdint>

namespace firmament {

namespace {
float latticeValue(glm::ivec3 c, unsigned octave) {
    const std::uint32_t h = hash32(static_cast<std::uint32_t>(c.x) ^
                                   hash32(static_cast<std::uint32_t>(c.y) ^ hash32(static_cast<std::uint32_t>(c.z) ^ hash32(octave + 0x632be5abu))));
    return static_cast<float>(h >> 8) * (1.0f / 16777216.0f);
}
float fade(float t) { return t * t * t * (t * (t * 6.0f - 15.0f) + 10.0f); }
float lerp(float a, float b, float t) { return a + t * (b - a); }
}  // namespace

float valueNoise3(glm::vec3 p, unsigned octave) {
    const glm::vec3 f(std::floor(p.x), std::floor(p.y), std::floor(p.z));
    const glm::vec3 t(fade(p.x - f.x), fade(p.y - f.y), fade(p.z - f.z));
    const glm::ivec3 c(f);
    auto v = [&](int x, int y, int z) { return latticeValue(c + glm::ivec3(x, y, z), octave); };
    const float x00 = lerp(v(0, 0, 0), v(1, 0, 0), t.x), x10 = lerp(v(0, 1, 0), v(1, 1, 0), t.x);
    const float x01 = lerp(v(0, 0, 1), v(1, 0, 1), t.x), x11 = lerp(v(0, 1, 1), v(1, 1, 1), t.x);
    return lerp(lerp(x00, x10, t.y), lerp(x01, x11, t.y), t.z);
}

float particleNoise(glm::vec3 p) {
    float sum = 0.0f, amplitude = 1.0f, frequency = 2.0f;
    for (unsigned o = 0; o < 4; ++o) {
        sum += (valueNoise3(p * frequency, o) - 0.5f) * amplitude;
        frequency *= 1.9f;
        amplitude *= 0.7f;
    }
    return sum;
}

float particleDensity(glm::vec3 p, ParticleDensityMethod method) {
    const float r = glm::length(p);
    if (r >= 1.0f) return 0.0f;
    const float falloff = (1.0f - r * r) * (1.0f - r * r) * (1.0f - r * r);
    if (method == ParticleDensityMethod::Pyroclastic) {
        const glm::vec3 onSphere = r > 1e-6f ? p / r : glm::vec3(0.0f, 1.0f, 0.0f);
        return r + 0.35f * particleNoise(onSphere) < 0.8f ? 1.0f : 0.0f;
    }
    const float perturbed = falloff + std::sqrt(falloff) * particleNoise(p);
    if (method == ParticleDensityMethod::ThresholdedNoise) return perturbed > 0.1f ? 1.0f : 0.0f;
    return std::clamp(perturbed, 0.0f, 1.0f);
}

}  // namespace firmament
