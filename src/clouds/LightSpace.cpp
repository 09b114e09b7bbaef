#include "clouds/LightSpace.h"

#include "clouds/OpticalDepthTable.h"

#include <glm/geometric.hpp>

#include <algorithm>
#include <cmath>

namespace firmament {

SunFrame sunFrame(glm::dvec3 toSun) {
    const glm::dvec3 sun = glm::normalize(toSun);
    const glm::dvec3 reference = std::abs(sun.y) < 0.99 ? glm::dvec3(0.0, 1.0, 0.0) : glm::dvec3(1.0, 0.0, 0.0);
    const glm::dvec3 right = glm::normalize(glm::cross(reference, sun));
    return {right, glm::cross(sun, right), sun};
}

gpu::CloudLightSpaceConstants lightSpaceConstants(const CloudSettings& settings, glm::dvec3 camera, glm::dvec3 toSun, unsigned nodeCapacity) {
    const auto [right, up, sun] = sunFrame(toSun);
    // The grid's corners are sqrt(2) particle distances away; the layer's height adds its shadow's length.
    const double halfWidth = settings.particleDistance * std::sqrt(2.0) + settings.altitude + settings.thickness;
    gpu::CloudLightSpaceConstants c{};
    c.centre = glm::vec4(static_cast<float>(camera.x), settings.altitude, static_cast<float>(camera.z), static_cast<float>(halfWidth));
    c.right = glm::vec4(glm::vec3(right), static_cast<float>(settings.lightSpaceResolution));
    c.up = glm::vec4(glm::vec3(up), settings.opacityEarlyExit ? static_cast<float>(kOpacityEarlyExitDepth) : 0.0f);
    c.sun = glm::vec4(glm::vec3(sun), static_cast<float>(nodeCapacity));
    return c;
}

}  // namespace firmament
