#include "postfx/ToneMappingCurves.h"

#include <algorithm>
#include <cmath>
#include <vector>

namespace firmament::tonemap {

double relativeLuminance(glm::dvec3 rgb) {
    return kLuminanceRed * rgb.r + kLuminanceGreen * rgb.g + kLuminanceBlue * rgb.b;
}

double exponential(double Ls) { return 1.0 - std::exp(-Ls); }

double reinhard(double Ls) { return Ls / (1.0 + Ls); }

double reinhardModified(double Ls, double Lw) { return Ls * (1.0 + Ls / (Lw * Lw)) / (1.0 + Ls); }

double logarithmic(double Ls, double Lw) { return std::log10(1.0 + Ls) / std::log10(1.0 + Lw); }

double adaptiveLogarithmic(double Ls, double Lw) {
    const double p = std::log(static_cast<double>(kDragoBias)) / std::log(0.5);
    return kDragoDisplayScale / std::log10(1.0 + Lw) * std::log(1.0 + Ls) / std::log(2.0 + 8.0 * std::pow(Ls / Lw, p));
}

double hableCurve(double x) {
    const double A = kHableShoulderStrength, B = kHableLinearStrength, C = kHableLinearAngle;
    const double D = kHableToeStrength, E = kHableToeNumerator, F = kHableToeDenominator;
    return (x * (A * x + C * B) + D * E) / (x * (A * x + B) + D * F) - E / F;
}

double uncharted2(double scaled, double Lw) { return hableCurve(kHableExposureBias * scaled) / hableCurve(Lw); }

double filmicAlu(double scaled) {
    const double x = std::max(0.0, scaled - kFilmicAluOffset);
    return x * (kFilmicAluA * x + kFilmicAluB) / (x * (kFilmicAluA * x + kFilmicAluC) + kFilmicAluD);
}

double srgbEncode(double linear) {
    linear = std::clamp(linear, 0.0, 1.0);
    return linear <= 0.0031308 ? 12.92 * linear : 1.055 * std::pow(linear, 1.0 / 2.4) - 0.055;
}

namespace {
double luminanceOperator(ToneMapOperator op, double Ls, double Lw) {
    switch (op) {
        case ToneMapOperator::Exp: return exponential(Ls);
        case ToneMapOperator::Reinhard: return reinhard(Ls);
        case ToneMapOperator::ReinhardModified: return reinhardModified(Ls, Lw);
        case ToneMapOperator::Logarithmic: return logarithmic(Ls, Lw);
        default: return adaptiveLogarithmic(Ls, Lw);
    }
}
}  // namespace

glm::dvec3 toDisplay(glm::dvec3 radiance, const Parameters& p) {
    const glm::dvec3 c = glm::clamp(radiance, 0.0, static_cast<double>(kMaxRadiance));
    if (p.op == ToneMapOperator::FilmicAlu)
        return glm::clamp(glm::dvec3(filmicAlu(p.exposure * c.r), filmicAlu(p.exposure * c.g), filmicAlu(p.exposure * c.b)), 0.0, 1.0);
    glm::dvec3 linear(0.0);
    if (p.op == ToneMapOperator::Uncharted2) {
        for (int i = 0; i < 3; ++i) linear[i] = uncharted2(p.exposure * c[i], p.whitePoint);
    } else {
        const double L = relativeLuminance(c);
        const double Ld = luminanceOperator(p.op, p.exposure * L, p.whitePoint);
        if (L > 0.0)
            for (int i = 0; i < 3; ++i) linear[i] = Ld * std::pow(c[i] / L, p.saturation);
    }
    return {srgbEncode(linear.r), srgbEncode(linear.g), srgbEncode(linear.b)};
}

double autoExposure(double averageLuminance, double middleGray, double compensation) {
    return middleGray / averageLuminance * compensation;
}

double meanLogLuminance(std::span<const glm::dvec3> pixels) {
    double sum = 0.0;
    for (const glm::dvec3& p : pixels)
        sum += std::log(kLogLuminanceDelta + relativeLuminance(glm::clamp(p, 0.0, static_cast<double>(kMaxRadiance))));
    return pixels.empty() ? std::log(static_cast<double>(kLogLuminanceDelta)) : sum / static_cast<double>(pixels.size());
}

double histogramMeanLogLuminance(std::span<const float> logTexels, double low, double high) {
    std::vector<double> counts(kHistogramBins, 0.0), sums(kHistogramBins, 0.0);
    const double black = std::log(static_cast<double>(kLogLuminanceDelta) + kBlackLuminance);
    const double range = static_cast<double>(kHistogramHighestLog) - kHistogramLowestLog;
    double total = 0.0, all = 0.0;
    for (float value : logTexels) {
        if (!(value > black)) continue;
        const double x = std::clamp((value - kHistogramLowestLog) / range, 0.0, 1.0);
        const int bin = std::min(static_cast<int>(x * kHistogramBins), kHistogramBins - 1);
        counts[bin] += 1.0;
        sums[bin] += kHistogramLowestLog + x * range;
        total += 1.0;
        all += kHistogramLowestLog + x * range;
    }
    if (total == 0.0) return std::log(static_cast<double>(kLogLuminanceDelta));
    const double from = low * total, to = high * total;
    double below = 0.0, sum = 0.0, weight = 0.0;
    for (int bin = 0; bin < kHistogramBins; ++bin) {
        if (counts[bin] == 0.0) continue;
        const double overlap = std::max(0.0, std::min(below + counts[bin], to) - std::max(below, from));
        sum += overlap * sums[bin] / counts[bin];
        weight += overlap;
        below += counts[bin];
    }
    return weight > 0.0 ? sum / weight : all / total;
}

double adaptationWeight(double dtSeconds, double timeConstantSeconds) {
    if (timeConstantSeconds <= 0.0) return 1.0;
    return 1.0 - std::exp(-std::max(dtSeconds, 0.0) / timeConstantSeconds);
}

}  // namespace firmament::tonemap
