// "Animate sun": the sun turns about the x axis at its rate, along a great circle, the same
// whatever the frame rate.
#include "atmosphere/SunAnimation.h"

#include <glm/glm.hpp>
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>

namespace firmament {
namespace {

float angleBetween(glm::vec3 a, glm::vec3 b) { return glm::degrees(std::acos(std::clamp(glm::dot(a, b), -1.0f, 1.0f))); }

TEST(SunAnimation, TurnsAtItsRateAboutTheXAxisWhateverTheFrameRate) {
    const Sun start{10.0f, 0.0f};  // 10 degrees up over +z
    for (const int steps : {1, 7, 60, 600}) {
        Sun sun = start;
        for (int i = 0; i < steps; ++i) animateSun(sun, 10.0f / steps);  // 10 s at 3 degrees a second
        EXPECT_NEAR(angleBetween(start.direction(), sun.direction()), 30.0f, 1e-3f) << steps << " steps";
        EXPECT_NEAR(sun.elevationDegrees, 40.0f, 1e-3f) << steps << " steps";  // rising over +z
        EXPECT_NEAR(sun.direction().x, start.direction().x, 1e-5f);           // about the x axis
    }
    // Past the zenith it sets on the other side, and it goes on below the horizon.
    Sun sun = start;
    animateSun(sun, 60.0f);  // 180 degrees
    EXPECT_NEAR(sun.elevationDegrees, -10.0f, 1e-3f);
    EXPECT_NEAR(std::abs(sun.azimuthDegrees), 180.0f, 1e-3f);
}

}  // namespace
}  // namespace firmament
