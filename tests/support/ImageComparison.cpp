#include "support/ImageComparison.h"

#include <algorithm>
#include <cmath>
#include <cstdlib>
#include <limits>
#include <stdexcept>

namespace firmament::test::golden {

namespace {
void requireSameSize(const Rgba8Image& a, const Rgba8Image& b) {
    if (a.width != b.width || a.height != b.height || a.pixels.size() != b.pixels.size())
        throw std::invalid_argument("images of different sizes cannot be compared");
}
}  // namespace

Comparison compare(const Rgba8Image& a, const Rgba8Image& b) {
    requireSameSize(a, b);
    Comparison c;
    double sumOfSquares = 0.0;
    for (int y = 0; y < a.height; ++y)
        for (int x = 0; x < a.width; ++x) {
            const std::uint8_t* p = a.pixel(x, y);
            const std::uint8_t* q = b.pixel(x, y);
            bool differs = false;
            for (int ch = 0; ch < 3; ++ch) {
                const int d = std::abs(static_cast<int>(p[ch]) - static_cast<int>(q[ch]));
                sumOfSquares += static_cast<double>(d) * d;
                differs |= d != 0;
                if (d > c.maxDifference) {
                    c.maxDifference = d;
                    c.worstPixel = glm::ivec2(x, y);
                }
            }
            c.differingPixels += differs;
        }
    const double samples = 3.0 * static_cast<double>(a.width) * static_cast<double>(a.height);
    c.meanSquaredError = samples > 0.0 ? sumOfSquares / samples : 0.0;
    c.psnrDb = c.meanSquaredError > 0.0 ? 10.0 * std::log10(255.0 * 255.0 / c.meanSquaredError)
                                        : std::numeric_limits<double>::infinity();
    return c;
}

Rgba8Image differenceImage(const Rgba8Image& a, const Rgba8Image& b) {
    requireSameSize(a, b);
    Rgba8Image out{a.width, a.height, std::vector<std::uint8_t>(a.pixels.size())};
    for (std::size_t i = 0; i < a.pixels.size(); i += 4) {
        for (int ch = 0; ch < 3; ++ch) {
            const int d = std::abs(static_cast<int>(a.pixels[i + ch]) - static_cast<int>(b.pixels[i + ch]));
            out.pixels[i + ch] = static_cast<std::uint8_t>(std::min(d * kDifferenceGain, 255));
        }
        out.pixels[i + 3] = 255;
    }
    return out;
}

}  // namespace firmament::test::golden
