#pragma once
// Comparing two 8-bit RGBA images of the same size over their RGB channels: the peak
// signal-to-noise ratio, PSNR = 10 log10(255^2 / MSE) (infinite when they are equal), and the
// largest difference of any channel of any pixel. The golden-image test states its tolerance
// in these two numbers.
#include "core/PngImage.h"

#include <glm/glm.hpp>

#include <cstddef>

namespace firmament::test::golden {

struct Comparison {
    double psnrDb = 0.0;        // infinity for equal images
    double meanSquaredError = 0.0;
    int maxDifference = 0;      // 8-bit steps
    glm::ivec2 worstPixel{0};   // where maxDifference is (the first such pixel)
    std::size_t differingPixels = 0;
};

// Throws std::invalid_argument when the sizes differ.
Comparison compare(const Rgba8Image& a, const Rgba8Image& b);

// |a - b| per channel times kDifferenceGain, clamped to 255, opaque: a difference of one step
// shows as kDifferenceGain.
inline constexpr int kDifferenceGain = 16;
Rgba8Image differenceImage(const Rgba8Image& a, const Rgba8Image& b);

}  // namespace firmament::test::golden
