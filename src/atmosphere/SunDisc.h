#pragma once
// The sun's disc as both atmosphere models draw it: its angular radius seen from the Earth, and
// the radiance of a uniform disc per unit irradiance, 1 / (its solid angle) = 1 / (2 pi (1 - cos r)).
#include <cmath>

namespace firmament {

inline constexpr double kSunAngularRadius = 0.00465;  // radians: 0.2666 degrees

inline double sunDiscRadiance() { return 1.0 / (2.0 * 3.14159265358979323846 * (1.0 - std::cos(kSunAngularRadius))); }

}  // namespace firmament
