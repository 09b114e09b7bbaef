#pragma once
// A perspective camera in Direct3D's conventions: left-handed, y up, x right, z forward,
// clip-space depth from 0 (near) to 1 (far). Orientation is yaw about +y then pitch.
#include <glm/glm.hpp>

namespace firmament {

struct Camera {
    glm::vec3 position{0.0f, 100.0f, 0.0f};  // metres above the ground plane
    float yawRadians = 0.0f;                  // 0 looks along +z
    float pitchRadians = 0.0f;                // positive looks up
    float verticalFovRadians = 0.7853982f;    // 45 degrees, as document 000's sample
    float nearPlane = 1.0f;                   // metres
    float farPlane = 1.0e6f;                  // metres

    glm::vec3 forward() const;
    glm::mat4 view() const;
    glm::mat4 projection(float aspectRatio) const;
};

// The direction towards the sun from elevation above the horizon and azimuth from +z
// towards +x, both in radians.
glm::vec3 directionFromElevationAzimuth(float elevation, float azimuth);

}  // namespace firmament
