#include "clouds/OpticalDepthTable.h"

#include "clouds/ParticleDensity.h"

#include <glm/geometric.hpp>

#include <algorithm>
#include <cmath>

namespace firmament {

namespace {
constexpr float kPi = 3.14159265f;

void entryFrame(glm::vec3 s, glm::vec3& x, glm::vec3& y, glm::vec3& z) {
    z = -s;
    const glm::vec3 side = glm::cross(z, glm::vec3(0.0f, 1.0f, 0.0f));
    const float length = glm::length(side);
    x = length > 1e-5f ? side / length : glm::vec3(1.0f, 0.0f, 0.0f);
    y = glm::cross(z, x);
}
}  // namespace

std::string OpticalDepthTableSize::describe() const {
    return std::to_string(entryZenith) + " x " + std::to_string(entryAzimuth) + " x " + std::to_string(directionZenith) + " x " +
           std::to_string(directionAzimuth) + " (entry zenith, entry azimuth, direction zenith, direction azimuth), " + std::to_string(steps) +
           " steps";
}

TableRay opticalDepthRay(glm::vec4 u) {
    const float thetaS = u.x * kPi, phiS = (u.y - 0.5f) * 2.0f * kPi;
    TableRay ray;
    ray.entry = glm::vec3(std::sin(thetaS) * std::cos(phiS), std::cos(thetaS), std::sin(thetaS) * std::sin(phiS));
    glm::vec3 x, y, z;
    entryFrame(ray.entry, x, y, z);
    const float thetaD = u.z * 0.5f * kPi, phiD = (u.w - 0.5f) * 2.0f * kPi;
    ray.direction = std::cos(thetaD) * z + std::sin(thetaD) * (std::cos(phiD) * x + std::sin(phiD) * y);
    return ray;
}

glm::vec4 opticalDepthCoordinates(glm::vec3 entry, glm::vec3 direction) {
    glm::vec3 x, y, z;
    entryFrame(entry, x, y, z);
    const float thetaS = std::acos(std::clamp(entry.y, -1.0f, 1.0f));
    const float phiS = std::atan2(entry.z, entry.x);
    const float thetaD = std::acos(std::clamp(glm::dot(direction, z), 0.0f, 1.0f));
    const float phiD = std::atan2(glm::dot(direction, y), glm::dot(direction, x));
    return {thetaS / kPi, phiS / (2.0f * kPi) + 0.5f, thetaD / (0.5f * kPi), phiD / (2.0f * kPi) + 0.5f};
}

glm::vec4 opticalDepthTexelCoordinates(const OpticalDepthTableSize& size, int x, int y, int z) {
    return (glm::vec4(static_cast<float>(y), static_cast<float>(x), static_cast<float>(z % size.directionZenith),
                      static_cast<float>(z / size.directionZenith)) +
            0.5f) /
           glm::vec4(static_cast<float>(size.entryZenith), static_cast<float>(size.entryAzimuth), static_cast<float>(size.directionZenith),
                     static_cast<float>(size.directionAzimuth));
}

float meanChordDensity(const TableRay& ray, int steps, ParticleDensityMethod method) {
    const float chord = 2.0f * glm::dot(-ray.entry, ray.direction);
    float sum = 0.0f;
    for (int k = 0; k < steps; ++k)
        sum += particleDensity(ray.entry + ray.direction * (chord * (static_cast<float>(k) + 0.5f) / static_cast<float>(steps)), method);
    return sum / static_cast<float>(steps);
}

}  // namespace firmament
