#include "atmosphere/SunAnimation.h"

#include <glm/trigonometric.hpp>

#include <algorithm>
#include <cmath>

namespace firmament {

void animateSun(Sun& sun, float dtSeconds, float degreesPerSecond) {
    const glm::vec3 d = sun.direction();
    const float angle = glm::radians(degreesPerSecond * dtSeconds);
    const float c = std::cos(angle), s = std::sin(angle);
    // Rotation about +x: y' = y c + z s, z' = -y s + z c (from +z up through the zenith).
    const glm::vec3 turned(d.x, d.y * c + d.z * s, -d.y * s + d.z * c);
    sun.elevationDegrees = glm::degrees(std::asin(std::clamp(turned.y, -1.0f, 1.0f)));
    if (std::abs(turned.x) > 1e-6f || std::abs(turned.z) > 1e-6f) sun.azimuthDegrees = glm::degrees(std::atan2(turned.x, turned.z));
}

}  // namespace firmament
