#pragma once
// A perspective camera in Direct3D's conventions: left-handed, y up, x right, z forward, with
// reversed Z: clip-space depth 1 at the near plane and 0 at the far plane (the depth buffer is
// cleared to 0 and tested GREATER_EQUAL). Orientation is yaw about +y then pitch.
// Angles are in degrees, as a person reads and types them in settings files.
#include "core/Settings.h"

#include <glm/glm.hpp>

namespace firmament {

struct Camera {
    glm::vec3 position{0.0f, 8000.0f, 0.0f};  // metres; y is the altitude above the ground plane
    float yawDegrees = 0.0f;                  // 0 looks along +z, 90 along +x
    float pitchDegrees = 0.0f;                // positive looks up
    float verticalFovDegrees = 45.0f;         // as Yusov 2013's sample
    float nearPlane = 1.0f;                   // metres: the nearest a view's near plane comes (withFittedNearPlane)
    float farPlane = 1.0e7f;                  // metres: beyond the horizon from orbit

    static constexpr float kMaxPitchDegrees = 89.0f;  // keeps lookAt's up vector valid

    glm::vec3 forward() const;
    glm::vec3 right() const;  // horizontal, to the right of forward
    glm::mat4 view() const;
    glm::mat4 projection(float aspectRatio) const;

    void visit(SettingsVisitor& v);  // section "camera"
};

// The direction towards the sun, from its elevation above the horizon and its azimuth
// from +z towards +x.
struct Sun {
    float elevationDegrees = 30.0f;
    float azimuthDegrees = 0.0f;

    glm::vec3 direction() const;
    void visit(SettingsVisitor& v);  // section "sun"
};

// The camera with its near plane at half its height above `highestSurface`, the highest point
// anything drawn can reach (nothing is nearer), and never nearer than camera.nearPlane. Reversed
// depth stores near / z, so from orbit a 1 m near plane would leave the whole Earth at depths under
// 1e-5, where Wine's wined3d keeps only about 1.4e-8 of absolute precision (measured by
// tests/gpu/DepthPrecisionTest.cpp): the distances to the ground came out in visible steps
// (docs/building.md, "Two Direct3D 11 implementations").
Camera withFittedNearPlane(Camera camera, double highestSurface);

glm::vec3 directionFromElevationAzimuth(float elevationRadians, float azimuthRadians);

}  // namespace firmament
