#pragma once
// Settings of the step from HDR radiance to the display (section "toneMapping"): exposure
// (manual, or automatic from the frame's average luminance with light adaptation), and the
// tone mapping operator with its controls. docs/tonemapping.md gives every formula.
#include "core/Settings.h"

#include <array>
#include <cmath>
#include <string_view>

namespace firmament {

// The order is the shader's operator index (shaders/postfx/tone_mapping_operators.hlsli).
enum class ToneMapOperator { Exp, Reinhard, ReinhardModified, Uncharted2, FilmicAlu, Logarithmic, AdaptiveLogarithmic };
inline constexpr std::array<std::string_view, 7> kToneMapOperatorNames{
    "Exp", "Reinhard", "Reinhard mod", "Uncharted 2", "Filmic ALU", "Logarithmic", "Adaptive log"};
inline constexpr int kToneMapOperatorCount = static_cast<int>(kToneMapOperatorNames.size());

// Which controls an operator reads (Yusov 2013, "Tone mapping controls").
constexpr bool usesWhitePoint(ToneMapOperator op) {
    return op == ToneMapOperator::ReinhardModified || op == ToneMapOperator::Uncharted2 ||
           op == ToneMapOperator::Logarithmic || op == ToneMapOperator::AdaptiveLogarithmic;
}
// Operators that map luminance and carry the colour over with the saturation exponent; the
// other two (Uncharted 2, Filmic ALU) map each colour channel on its own.
constexpr bool usesLuminanceSaturation(ToneMapOperator op) {
    return op != ToneMapOperator::Uncharted2 && op != ToneMapOperator::FilmicAlu;
}

// "Metering": how auto exposure measures the frame's luminance. Histogram: the log-average of
// the pixels that are not black, between two percentiles of a luminance histogram (space, the
// sun's disc and specular glints do not drag it); Log average: of every pixel (Reinhard et al.
// 2002, eq. 1, Yusov's sample).
enum class Metering { Histogram, LogAverage };
inline constexpr std::array<std::string_view, 2> kMeteringNames{"Histogram", "Log average"};

struct ToneMappingSettings {
    ToneMapOperator op = ToneMapOperator::Uncharted2;
    float middleGray = 0.18f;           // the key: where auto exposure puts the average luminance
    float whitePoint = 3.0f;            // scaled luminance that maps to display white
    float luminanceSaturation = 1.0f;   // exponent on colour / luminance (1 keeps the hue and saturation)
    bool autoExposure = true;           // exposure from the frame's log-average luminance
    Metering metering = Metering::Histogram;
    float histogramLow = 0.1f;          // the darkest share of the pixels left out of the histogram's average
    float histogramHigh = 0.98f;        // the share below which the average stops (the brightest are left out)
    bool lightAdaptation = true;        // the measured average follows the scene over time
    float adaptationSeconds = 0.5f;     // time constant of that adaptation
    float exposureEv = 0.0f;            // manual exposure, or compensation on top of auto exposure

    // 2^EV: the whole exposure without auto exposure, a factor on top of it with.
    float exposureCompensation() const { return std::exp2(exposureEv); }

    void visit(SettingsVisitor& v) {
        v.choice("operator", op, kToneMapOperatorNames, "Tone mapping operator");
        v.field("middleGray", middleGray, {0.01f, 1.0f}, "Middle gray (key)");
        v.field("whitePoint", whitePoint, {0.01f, 10.0f}, "White point");
        v.field("luminanceSaturation", luminanceSaturation, {0.01f, 2.0f}, "Luminance saturation");
        v.field("autoExposure", autoExposure, "Auto exposure");
        v.choice("metering", metering, kMeteringNames, "Metering");
        v.field("histogramLow", histogramLow, {0.0f, 0.5f}, "Histogram low percentile");
        v.field("histogramHigh", histogramHigh, {0.5f, 1.0f}, "Histogram high percentile");
        v.field("lightAdaptation", lightAdaptation, "Light adaptation");
        v.field("adaptationSeconds", adaptationSeconds, {0.02f, 10.0f, true}, "Adaptation time (s)");
        v.field("exposure", exposureEv, {-10.0f, 10.0f}, "Exposure (EV)");
    }
};

}  // namespace firmament
