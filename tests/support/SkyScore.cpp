#include "support/SkyScore.h"

#include <algorithm>
#include <cmath>
#include <limits>

namespace firmament::test {

std::vector<PixelRay> sampledRays(const FloatExrFile& capture, int columns, int rows, double sunMargin) {
    glm::mat4 view = std::get<glm::mat4>(capture.attributes.at("firmament.view"));
    view[3] = glm::vec4(0.0f, 0.0f, 0.0f, 1.0f);  // directions only
    const glm::mat4 clipToDirection = glm::inverse(std::get<glm::mat4>(capture.attributes.at("firmament.projection")) * view);
    const glm::dvec3 sun = directionToSun(capture);
    const int width = capture.image.width, height = capture.image.height;
    std::vector<PixelRay> rays;
    for (int j = 0; j < rows; ++j)
        for (int i = 0; i < columns; ++i) {
            const int x = (2 * i + 1) * width / (2 * columns), y = (2 * j + 1) * height / (2 * rows);
            const glm::vec4 ndc((x + 0.5f) / width * 2.0f - 1.0f, 1.0f - (y + 0.5f) / height * 2.0f, 1.0f, 1.0f);
            const glm::vec4 farPoint = clipToDirection * ndc;
            const glm::dvec3 direction = glm::normalize(glm::dvec3(farPoint) / static_cast<double>(farPoint.w));
            if (glm::dot(direction, sun) > std::cos(sunMargin)) continue;
            rays.push_back({x, y, direction});
        }
    return rays;
}

glm::dvec3 directionToSun(const FloatExrFile& capture) { return glm::dvec3(std::get<glm::vec3>(capture.attributes.at("firmament.directionToSun"))); }

atmosphere::ReferenceAtmosphere::Estimate referenceRadiance(const atmosphere::ReferenceAtmosphere& reference, glm::dvec3 start, glm::dvec3 view,
                                                            glm::dvec3 sun, int paths, unsigned seed,
                                                            atmosphere::ReferenceAtmosphere::PathSampling sampling) {
    // From above the atmosphere the view starts where it enters it; one that misses it is dark.
    const double top = reference.parameters().topRadius();
    if (glm::length(start) > top) {
        const double b = glm::dot(start, view), c = glm::dot(start, start) - top * top, discriminant = b * b - c;
        if (discriminant <= 0.0 || -b - std::sqrt(discriminant) <= 0.0) return {glm::dvec3(0.0), glm::dvec3(0.0)};
        start += view * (-b - std::sqrt(discriminant));
        start *= (top - 1e-3) / glm::length(start);  // just inside
    }
    auto higher = reference.highOrderScattering(start, view, sun, kScoreOrders, paths, seed, sampling);
    higher.mean += reference.singleScattering(start, view, sun);
    return higher;
}

double luminance(glm::dvec3 rgb) { return 0.2126 * rgb.r + 0.7152 * rgb.g + 0.0722 * rgb.b; }

SkyScore scoreSky(const std::vector<glm::dvec3>& model, const std::vector<glm::dvec3>& reference) {
    SkyScore s;
    double peak = 0.0, squares = 0.0, brightest = 0.0;
    for (const glm::dvec3& r : reference) {
        peak = std::max({peak, r.r, r.g, r.b});
        brightest = std::max(brightest, luminance(r));
    }
    std::vector<double> errors;
    for (size_t i = 0; i < model.size(); ++i) {
        const glm::dvec3 d = model[i] - reference[i];
        squares += glm::dot(d, d);
        const double y = luminance(reference[i]);
        if (y > 1e-9 * brightest && y > 0.0) errors.push_back(std::abs(luminance(model[i]) - y) / y);
    }
    const double mse = squares / (3.0 * std::max<size_t>(model.size(), 1));
    s.hdrPsnrDb = mse > 0.0 ? 10.0 * std::log10(peak * peak / mse) : std::numeric_limits<double>::infinity();
    s.pixels = errors.size();
    if (!errors.empty()) {
        std::sort(errors.begin(), errors.end());
        s.medianRelativeError = errors[errors.size() / 2];
        s.p95RelativeError = errors[std::min(errors.size() - 1, errors.size() * 95 / 100)];
    }
    return s;
}

glm::dvec3 capturedRadiance(const FloatExrFile& capture, int x, int y) {
    const float* rgba = &capture.image.rgba[(static_cast<size_t>(y) * capture.image.width + x) * 4];
    return {rgba[0], rgba[1], rgba[2]};
}

}  // namespace firmament::test
