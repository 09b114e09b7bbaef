#pragma once
// The sun's disc as every atmosphere model draws it: its angular radius seen from the Earth, and
// the radiance of a uniform disc per unit irradiance, 1 / (its solid angle) = 1 / (2 pi (1 - cos r)).
#include <glm/vec4.hpp>

#include <cmath>

namespace firmament {

inline constexpr double kSunAngularRadius = 0.00465;  // radians: 0.2666 degrees

inline double sunDiscRadiance() { return 1.0 / (2.0 * 3.14159265358979323846 * (1.0 - std::cos(kSunAngularRadius))); }

// The disc as the models' pass constants hold it: x the cosine of its angular radius, y its
// radiance per unit irradiance.
inline glm::vec4 sunDiscConstants() {
    return glm::vec4(static_cast<float>(std::cos(kSunAngularRadius)), static_cast<float>(sunDiscRadiance()), 0.0f, 0.0f);
}

}  // namespace firmament
