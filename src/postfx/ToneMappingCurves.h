#pragma once
// The tone mapping operators, light adaptation and the log-average luminance on the CPU, in
// double precision: the reference the GPU passes are tested against, written from the papers
// (docs/tonemapping.md) and sharing only the constants with the shaders.
#include "postfx/ToneMappingSettings.h"

#include <glm/glm.hpp>

#include <span>

namespace firmament::tonemap {

#include "postfx/tone_mapping_constants.hlsli"

double relativeLuminance(glm::dvec3 rgb);  // ITU-R BT.709 weights

// Luminance operators: scaled luminance Ls (and white point Lw) to display luminance Ld.
double exponential(double Ls);                           // 1 - exp(-Ls)
double reinhard(double Ls);                              // Reinhard et al. 2002, eq. 3
double reinhardModified(double Ls, double Lw);           // Reinhard et al. 2002, eq. 4
double logarithmic(double Ls, double Lw);                // Drago et al. 2003, plain log mapping
double adaptiveLogarithmic(double Ls, double Lw);        // Drago et al. 2003, eq. 4
// Channel operators.
double hableCurve(double x);                             // Hable 2010, the filmic curve f(x)
double uncharted2(double scaled, double Lw);             // f(bias x) / f(Lw), linear
double filmicAlu(double scaled);                         // Hable 2010, display encoded

double srgbEncode(double linear);  // IEC 61966-2-1, input clamped to [0, 1]

struct Parameters {
    ToneMapOperator op = ToneMapOperator::Uncharted2;
    double exposure = 1.0;    // radiance to scaled luminance
    double whitePoint = 3.0;  // Lw
    double saturation = 1.0;  // s in Ld (C / L)^s
};

// Radiance to display-encoded colour in [0, 1]: what the tone mapping pass writes.
glm::dvec3 toDisplay(glm::dvec3 radiance, const Parameters& p);

// Exposure that brings the log-average luminance to the middle grey (Reinhard et al. 2002,
// eq. 2: Ls = key / Lavg * L), times the compensation 2^EV.
double autoExposure(double averageLuminance, double middleGray, double compensation);

// ln(delta + L), averaged over `pixels` (RGB triples): the log-average luminance's logarithm
// (Reinhard et al. 2002, eq. 1).
double meanLogLuminance(std::span<const glm::dvec3> pixels);

// Histogram metering (postfx/luminance_histogram.hlsl): of the values ln(delta + L) of the
// measurement's 64 x 64 texels, those above ln(delta + kBlackLuminance), binned over
// [kHistogramLowestLog, kHistogramHighestLog], averaged between the `low` and `high` shares of
// their count (each bin's values by their mean); ln(delta) when every texel is black.
double histogramMeanLogLuminance(std::span<const float> logTexels, double low, double high);

// Light adaptation: the fraction of the way from the adapted log luminance to the measured
// one covered in a frame of `dt` seconds, 1 - exp(-dt / tau). Frames compose: two steps of
// dt cover what one step of 2 dt does, so the adaptation does not depend on the frame rate.
double adaptationWeight(double dtSeconds, double timeConstantSeconds);

}  // namespace firmament::tonemap
