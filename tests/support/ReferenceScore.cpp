#include "support/ReferenceScore.h"

#include "postfx/ToneMappingCurves.h"
#include "support/ImageComparison.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <stdexcept>
#include <vector>

namespace firmament::test {
namespace {

double luminance(const FloatRgbaImage& image, size_t pixel) {
    const float* c = &image.rgba[pixel * 4];
    return 0.2126 * c[0] + 0.7152 * c[1] + 0.0722 * c[2];
}

// The sums over the technique's pixels that the means and ratios are made of.
struct PixelSums {
    double luminance = 0.0, red = 0.0, blue = 0.0;
    void add(const FloatRgbaImage& image, size_t pixel) {
        luminance += test::luminance(image, pixel);
        red += image.rgba[pixel * 4];
        blue += image.rgba[pixel * 4 + 2];
    }
    FrameSums over(size_t pixels) const { return {pixels ? luminance / static_cast<double>(pixels) : 0.0, blue > 0.0 ? red / blue : 0.0}; }
};

// The frame at `exposure` through the default operator, display-encoded in 8 bits.
Rgba8Image toneMapped(const FloatRgbaImage& image, double exposure) {
    tonemap::Parameters p;
    p.exposure = exposure;
    Rgba8Image out{image.width, image.height, {}};
    out.pixels.reserve(image.rgba.size());
    for (size_t i = 0; i < image.rgba.size(); i += 4) {
        const glm::dvec3 display = tonemap::toDisplay(glm::dvec3(image.rgba[i], image.rgba[i + 1], image.rgba[i + 2]), p);
        for (int k = 0; k < 3; ++k) out.pixels.push_back(static_cast<std::uint8_t>(std::lround(std::clamp(display[k], 0.0, 1.0) * 255.0)));
        out.pixels.push_back(255);
    }
    return out;
}

}  // namespace

ReferenceScore scoreAgainstReference(const FloatRgbaImage& reference, const FloatRgbaImage& candidate, const FloatRgbaImage& clear) {
    const FloatRgbaImage &r = reference, &c = candidate, &z = clear;
    if (r.width != c.width || r.height != c.height || r.width != z.width || r.height != z.height)
        throw std::invalid_argument("the reference, the candidate and the clear view differ in size");
    ReferenceScore score;
    const size_t count = static_cast<size_t>(r.width) * r.height;
    std::vector<float> values;
    values.reserve(count * 3);
    double squared = 0.0;
    for (size_t p = 0; p < count; ++p)
        for (int k = 0; k < 3; ++k) {
            values.push_back(r.rgba[p * 4 + k]);
            const double d = static_cast<double>(c.rgba[p * 4 + k]) - r.rgba[p * 4 + k];
            squared += d * d;
        }
    const size_t rank = values.size() * 999 / 1000;
    std::nth_element(values.begin(), values.begin() + static_cast<std::ptrdiff_t>(rank), values.end());
    const double peak = values[rank];
    const double mse = squared / static_cast<double>(count * 3);
    score.hdrPsnrDb = mse > 0.0 ? 10.0 * std::log10(peak * peak / mse) : std::numeric_limits<double>::infinity();

    PixelSums onReference, onCandidate;
    for (size_t p = 0; p < count; ++p) {
        const double base = luminance(z, p);
        const double bound = 0.05 * base + 1e-6;
        if (std::abs(luminance(r, p) - base) <= bound && std::abs(luminance(c, p) - base) <= bound) continue;
        ++score.pixels;
        onReference.add(r, p);
        onCandidate.add(c, p);
    }
    score.reference = onReference.over(score.pixels);
    score.candidate = onCandidate.over(score.pixels);
    score.meanLuminanceRatio = score.reference.meanLuminance > 0.0 ? score.candidate.meanLuminance / score.reference.meanLuminance : 0.0;
    score.redOverBlueRatio = score.reference.redOverBlue > 0.0 ? score.candidate.redOverBlue / score.reference.redOverBlue : 0.0;

    std::vector<glm::dvec3> radiance(count);
    for (size_t p = 0; p < count; ++p) radiance[p] = glm::dvec3(r.rgba[p * 4], r.rgba[p * 4 + 1], r.rgba[p * 4 + 2]);
    score.exposure = tonemap::autoExposure(std::exp(tonemap::meanLogLuminance(radiance)), 0.18, 1.0);
    score.referenceShown = toneMapped(r, score.exposure);
    score.candidateShown = toneMapped(c, score.exposure);
    score.toneMappedPsnrDb = golden::compare(score.referenceShown, score.candidateShown).psnrDb;
    return score;
}

Rgba8Image sideBySide(const ReferenceScore& score) {
    constexpr int kGap = 4;
    const Rgba8Image &left = score.candidateShown, &right = score.referenceShown;
    Rgba8Image both{left.width * 2 + kGap, left.height, {}};
    both.pixels.assign(static_cast<size_t>(both.width) * both.height * 4, 255);
    for (int y = 0; y < left.height; ++y)
        for (int part = 0; part < 2; ++part)
            std::copy_n((part ? right : left).pixel(0, y), left.width * 4,
                        both.pixels.begin() + (static_cast<std::ptrdiff_t>(y) * both.width + part * (left.width + kGap)) * 4);
    return both;
}

}  // namespace firmament::test
