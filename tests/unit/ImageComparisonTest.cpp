// The golden-image test's measures against hand-computed values: PSNR = 10 log10(255^2 / MSE)
// over the RGB channels, the largest difference and where it is, and the difference image.
#include "support/ImageComparison.h"

#include <gtest/gtest.h>

#include <cmath>
#include <stdexcept>

namespace firmament::test::golden {
namespace {

Rgba8Image solid(int width, int height, std::uint8_t r, std::uint8_t g, std::uint8_t b) {
    Rgba8Image image{width, height, {}};
    for (int i = 0; i < width * height; ++i) image.pixels.insert(image.pixels.end(), {r, g, b, 255});
    return image;
}

TEST(ImageComparison, EqualImagesHaveInfinitePsnrAndNoDifference) {
    const Rgba8Image a = solid(4, 3, 10, 20, 30);
    const Comparison c = compare(a, a);
    EXPECT_TRUE(std::isinf(c.psnrDb));
    EXPECT_EQ(c.maxDifference, 0);
    EXPECT_EQ(c.differingPixels, 0u);
}

TEST(ImageComparison, PsnrOfOneChangedChannelMatchesTheFormula) {
    const Rgba8Image a = solid(4, 4, 100, 100, 100);
    Rgba8Image b = a;
    b.pixels[(2 * 4 + 3) * 4 + 1] = 110;  // pixel (3, 2), green +10
    b.pixels[3] = 0;                      // alpha is not compared
    const Comparison c = compare(a, b);
    const double mse = 100.0 / (3.0 * 16.0);
    EXPECT_NEAR(c.meanSquaredError, mse, 1e-12);
    EXPECT_NEAR(c.psnrDb, 10.0 * std::log10(255.0 * 255.0 / mse), 1e-9);
    EXPECT_NEAR(c.psnrDb, 44.94, 0.01);  // by hand: 10 log10(65025 / 2.0833)
    EXPECT_EQ(c.maxDifference, 10);
    EXPECT_EQ(c.worstPixel, glm::ivec2(3, 2));
    EXPECT_EQ(c.differingPixels, 1u);
}

TEST(ImageComparison, DifferenceImageAmplifiesAndClamps) {
    const Rgba8Image a = solid(2, 1, 0, 0, 0);
    Rgba8Image b = solid(2, 1, 1, 100, 0);
    const Rgba8Image d = differenceImage(a, b);
    EXPECT_EQ(d.pixels[0], kDifferenceGain);
    EXPECT_EQ(d.pixels[1], 255);
    EXPECT_EQ(d.pixels[2], 0);
    EXPECT_EQ(d.pixels[3], 255);
}

TEST(ImageComparison, RefusesImagesOfDifferentSizes) {
    EXPECT_THROW(compare(solid(2, 2, 0, 0, 0), solid(2, 3, 0, 0, 0)), std::invalid_argument);
}

}  // namespace
}  // namespace firmament::test::golden
