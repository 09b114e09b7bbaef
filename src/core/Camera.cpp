#include "core/Camera.h"

#include <glm/ext/matrix_clip_space.hpp>
#include <glm/ext/matrix_transform.hpp>
#include <glm/trigonometric.hpp>

#include <algorithm>
#include <cmath>

namespace firmament {

glm::vec3 Camera::forward() const {
    return directionFromElevationAzimuth(glm::radians(pitchDegrees), glm::radians(yawDegrees));
}

glm::vec3 Camera::right() const {
    const float yaw = glm::radians(yawDegrees);
    return {std::cos(yaw), 0.0f, -std::sin(yaw)};
}

glm::mat4 Camera::view() const {
    return glm::lookAtLH(position, position + forward(), glm::vec3(0.0f, 1.0f, 0.0f));
}

glm::mat4 Camera::projection(float aspectRatio) const {
    // Reversed Z: the planes swapped put depth 1 at the near plane and 0 at the far one, so that
    // float depth's precision, densest near 0, goes to the far distances.
    return glm::perspectiveLH_ZO(glm::radians(verticalFovDegrees), aspectRatio, farPlane, nearPlane);
}

Camera withFittedNearPlane(Camera camera, double highestSurface) {
    const double clearance = static_cast<double>(camera.position.y) - highestSurface;
    camera.nearPlane = std::max(camera.nearPlane, static_cast<float>(0.5 * clearance));
    return camera;
}

void Camera::visit(SettingsVisitor& v) {
    v.field("position", position, "Position (m)");
    v.field("yaw", yawDegrees, {-180.0f, 180.0f}, "Yaw (degrees)");
    v.field("pitch", pitchDegrees, {-kMaxPitchDegrees, kMaxPitchDegrees}, "Pitch (degrees)");
    v.field("fieldOfView", verticalFovDegrees, {10.0f, 120.0f}, "Vertical field of view (degrees)");
}

glm::vec3 Sun::direction() const {
    return directionFromElevationAzimuth(glm::radians(elevationDegrees), glm::radians(azimuthDegrees));
}

void Sun::visit(SettingsVisitor& v) {
    v.field("elevation", elevationDegrees, {-90.0f, 90.0f}, "Sun elevation (degrees)");
    v.field("azimuth", azimuthDegrees, {-180.0f, 180.0f}, "Sun azimuth (degrees)");
}

glm::vec3 directionFromElevationAzimuth(float elevation, float azimuth) {
    return {std::cos(elevation) * std::sin(azimuth), std::sin(elevation), std::cos(elevation) * std::cos(azimuth)};
}

}  // namespace firmament
