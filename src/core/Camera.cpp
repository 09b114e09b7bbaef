#include "core/Camera.h"

#include <glm/ext/matrix_clip_space.hpp>
#include <glm/ext/matrix_transform.hpp>

#include <cmath>

namespace firmament {

glm::vec3 Camera::forward() const {
    return {std::cos(pitchRadians) * std::sin(yawRadians), std::sin(pitchRadians),
            std::cos(pitchRadians) * std::cos(yawRadians)};
}

glm::mat4 Camera::view() const {
    return glm::lookAtLH(position, position + forward(), glm::vec3(0.0f, 1.0f, 0.0f));
}

glm::mat4 Camera::projection(float aspectRatio) const {
    return glm::perspectiveLH_ZO(verticalFovRadians, aspectRatio, nearPlane, farPlane);
}

glm::vec3 directionFromElevationAzimuth(float elevation, float azimuth) {
    return {std::cos(elevation) * std::sin(azimuth), std::sin(elevation), std::cos(elevation) * std::cos(azimuth)};
}

}  // namespace firmament
