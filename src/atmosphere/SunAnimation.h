#pragma once
// "Animate sun" (Yusov 2013's Additional panel): the sun turns at a steady rate about the
// world's x axis, so that it rises over +z, crosses the zenith and sets towards -z, and the
// twilight and the night come round. Each step is an exact rotation, so the path does not
// depend on the frame rate.
#include "core/Camera.h"

namespace firmament {

inline constexpr float kSunAnimationDegreesPerSecond = 3.0f;  // a whole day in two minutes

// Turns `sun` by degreesPerSecond * dtSeconds about the x axis (positive: from +z through the
// zenith towards -z), keeping it a unit direction expressed as elevation and azimuth.
void animateSun(Sun& sun, float dtSeconds, float degreesPerSecond = kSunAnimationDegreesPerSecond);

}  // namespace firmament
