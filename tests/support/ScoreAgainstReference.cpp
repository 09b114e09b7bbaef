// firmament_score_against_reference REFERENCE.exr CANDIDATE.exr CLEAR.exr SIDE_BY_SIDE.png: a
// frame scored against a reference frame of the same view (tools/clouds-against-reference: the
// particles against the clouds' path-traced reference), from the captures' radiance before
// tone mapping. CLEAR is the view without the technique; the technique's pixels are those where
// either frame's luminance differs from CLEAR's by more than 5%. Both frames are tone-mapped
// here, at one exposure: the reference's log-average luminance brought to middle grey 0.18
// (Reinhard et al. 2002, eq. 2), by the default operator (Uncharted 2, white point 3) through
// the CPU curves the tone mapping pass is tested against, so that neither frame's own
// automatic exposure enters the comparison. Writes the two side by side (candidate left) and
// prints one JSON object:
//  - hdrPsnrDb: 10 log10(P^2 / MSE) over every channel of every pixel, P the reference's 99.9th
//    percentile of channel values (a percentile, so that a few unconverged bright paths do not
//    set the scale);
//  - toneMappedPsnrDb: the golden test's PSNR of the two tone-mapped 8-bit frames;
//  - pixels: the technique's pixels; for each frame over them, meanLuminance (Rec. 709 Y of the
//    radiance) and redOverBlue (the sum of red over the sum of blue), and their ratios, candidate
//    over reference.
#include "core/ExrImage.h"
#include "postfx/ToneMappingCurves.h"
#include "support/ImageComparison.h"

#include <nlohmann/json.hpp>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <exception>
#include <string>
#include <vector>

namespace {

using firmament::FloatRgbaImage;

double luminance(const FloatRgbaImage& image, size_t pixel) {
    const float* c = &image.rgba[pixel * 4];
    return 0.2126 * c[0] + 0.7152 * c[1] + 0.0722 * c[2];
}

// The sums over the technique's pixels that the means and ratios are made of.
struct PixelSums {
    double luminance = 0.0, red = 0.0, blue = 0.0;
    void add(const FloatRgbaImage& image, size_t pixel) {
        luminance += ::luminance(image, pixel);
        red += image.rgba[pixel * 4];
        blue += image.rgba[pixel * 4 + 2];
    }
};

// The frame at `exposure` through the default operator, display-encoded in 8 bits.
firmament::Rgba8Image toneMapped(const FloatRgbaImage& image, double exposure) {
    firmament::tonemap::Parameters p;
    p.exposure = exposure;
    firmament::Rgba8Image out{image.width, image.height, {}};
    out.pixels.reserve(image.rgba.size());
    for (size_t i = 0; i < image.rgba.size(); i += 4) {
        const glm::dvec3 display = firmament::tonemap::toDisplay(glm::dvec3(image.rgba[i], image.rgba[i + 1], image.rgba[i + 2]), p);
        for (int k = 0; k < 3; ++k) out.pixels.push_back(static_cast<std::uint8_t>(std::lround(std::clamp(display[k], 0.0, 1.0) * 255.0)));
        out.pixels.push_back(255);
    }
    return out;
}

nlohmann::json describe(const PixelSums& s, size_t pixels) {
    return {{"meanLuminance", pixels ? s.luminance / static_cast<double>(pixels) : 0.0}, {"redOverBlue", s.blue > 0.0 ? s.red / s.blue : 0.0}};
}

}  // namespace

int main(int argc, char** argv) {
    using namespace firmament;
    if (argc != 5) {
        std::fprintf(stderr, "usage: firmament_score_against_reference REFERENCE.exr CANDIDATE.exr CLEAR.exr SIDE_BY_SIDE.png\n");
        return 2;
    }
    try {
        const FloatRgbaImage r = readFloatExr(argv[1]).image;
        const FloatRgbaImage c = readFloatExr(argv[2]).image;
        const FloatRgbaImage z = readFloatExr(argv[3]).image;
        if (r.width != c.width || r.height != c.height || r.width != z.width || r.height != z.height) {
            std::fprintf(stderr, "the three captures differ in size\n");
            return 1;
        }
        const size_t count = static_cast<size_t>(r.width) * r.height;
        std::vector<float> values;
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
        PixelSums onReference, onCandidate;
        size_t pixels = 0;
        for (size_t p = 0; p < count; ++p) {
            const double base = luminance(z, p);
            const double bound = 0.05 * base + 1e-6;
            if (std::abs(luminance(r, p) - base) <= bound && std::abs(luminance(c, p) - base) <= bound) continue;
            ++pixels;
            onReference.add(r, p);
            onCandidate.add(c, p);
        }
        std::vector<glm::dvec3> radiance(count);
        for (size_t p = 0; p < count; ++p) radiance[p] = glm::dvec3(r.rgba[p * 4], r.rgba[p * 4 + 1], r.rgba[p * 4 + 2]);
        const double exposure = tonemap::autoExposure(std::exp(tonemap::meanLogLuminance(radiance)), 0.18, 1.0);
        const Rgba8Image referenceShown = toneMapped(r, exposure), candidateShown = toneMapped(c, exposure);
        const test::golden::Comparison toneMapped = test::golden::compare(referenceShown, candidateShown);
        constexpr int kGap = 4;
        Rgba8Image both{r.width * 2 + kGap, r.height, {}};
        both.pixels.assign(static_cast<size_t>(both.width) * both.height * 4, 255);
        for (int y = 0; y < r.height; ++y)
            for (int part = 0; part < 2; ++part)
                std::copy_n((part ? referenceShown : candidateShown).pixel(0, y), r.width * 4,
                            both.pixels.begin() + (static_cast<std::ptrdiff_t>(y) * both.width + part * (r.width + kGap)) * 4);
        writePng(argv[4], both);
        nlohmann::json out{{"exposure", exposure},
                           {"hdrPsnrDb", mse > 0.0 ? 10.0 * std::log10(peak * peak / mse) : 999.0},
                           {"toneMappedPsnrDb", std::isfinite(toneMapped.psnrDb) ? toneMapped.psnrDb : 999.0},
                           {"pixels", pixels},
                           {"reference", describe(onReference, pixels)},
                           {"candidate", describe(onCandidate, pixels)}};
        const double refMean = out["reference"]["meanLuminance"], candMean = out["candidate"]["meanLuminance"];
        const double refRb = out["reference"]["redOverBlue"], candRb = out["candidate"]["redOverBlue"];
        out["meanLuminanceRatio"] = refMean > 0.0 ? candMean / refMean : 0.0;
        out["redOverBlueRatio"] = refRb > 0.0 ? candRb / refRb : 0.0;
        std::printf("%s\n", out.dump().c_str());
        return 0;
    } catch (const std::exception& e) {
        std::fprintf(stderr, "%s\n", e.what());
        return 1;
    }
}
