#ifndef FIRMAMENT_TONE_MAPPING_OPERATORS_HLSLI
#define FIRMAMENT_TONE_MAPPING_OPERATORS_HLSLI
// The seven tone mapping operators of Yusov 2013 ("Tone mapping"), from scaled radiance to
// display values. docs/tonemapping.md gives each formula with its source; the CPU reference
// (src/postfx/ToneMappingCurves.cpp) computes the same in double precision for the tests.
//
// Names: L is the luminance of the frame's radiance, Ls = exposure * L the scaled luminance
// (Reinhard's L(x, y)), Lw the white point in the same units, Ld the display luminance.
#include "common/srgb.hlsli"
#include "postfx/tone_mapping_constants.hlsli"

// Operator indices: the order of ToneMapOperator (src/postfx/ToneMappingSettings.h).
#define TONE_MAP_EXP 0
#define TONE_MAP_REINHARD 1
#define TONE_MAP_REINHARD_MODIFIED 2
#define TONE_MAP_UNCHARTED_2 3
#define TONE_MAP_FILMIC_ALU 4
#define TONE_MAP_LOGARITHMIC 5
#define TONE_MAP_ADAPTIVE_LOGARITHMIC 6

float relativeLuminance(float3 rgb) {
    return dot(rgb, float3(kLuminanceRed, kLuminanceGreen, kLuminanceBlue));
}

// Ld = 1 - exp(-Ls).
float toneMapExp(float Ls) {
    return 1.0 - exp(-Ls);
}

// Reinhard et al. 2002, eq. 3: Ld = Ls / (1 + Ls).
float toneMapReinhard(float Ls) {
    return Ls / (1.0 + Ls);
}

// Reinhard et al. 2002, eq. 4: Ld = Ls (1 + Ls / Lw^2) / (1 + Ls), written as a product so
// that a huge Ls gives +inf (clamped to white later), never inf / inf.
float toneMapReinhardModified(float Ls, float Lw) {
    return Ls / (1.0 + Ls) * (1.0 + Ls / (Lw * Lw));
}

// Hable 2010: the filmic curve f(x) = (x (A x + C B) + D E) / (x (A x + B) + D F) - E / F.
float3 hableCurve(float3 x) {
    const float A = kHableShoulderStrength, B = kHableLinearStrength, C = kHableLinearAngle;
    const float D = kHableToeStrength, E = kHableToeNumerator, F = kHableToeDenominator;
    return (x * (A * x + C * B) + D * E) / (x * (A * x + B) + D * F) - E / F;
}

// Uncharted 2, per channel: f(bias c) / f(Lw), linear output.
float3 toneMapUncharted2(float3 scaled, float Lw) {
    return hableCurve(kHableExposureBias * scaled) / hableCurve(Lw).x;
}

// Filmic ALU (Hable 2010, after Hejl and Burgess-Dawson), per channel. Its output is already
// display encoded (the curve folds in a 1/2.2 gamma): no sRGB encoding follows.
float3 toneMapFilmicAlu(float3 scaled) {
    float3 x = max(0.0, scaled - kFilmicAluOffset);
    return (x * (kFilmicAluA * x + kFilmicAluB)) / (x * (kFilmicAluA * x + kFilmicAluC) + kFilmicAluD);
}

// Drago et al. 2003, the plain logarithmic mapping: Ld = log10(1 + Ls) / log10(1 + Lw).
float toneMapLogarithmic(float Ls, float Lw) {
    return log10(1.0 + Ls) / log10(1.0 + Lw);
}

// Drago et al. 2003, eq. 4, the adaptive logarithmic mapping with bias b:
//   Ld = (Ldmax / 100) / log10(1 + Lw) * ln(1 + Ls) / ln(2 + 8 (Ls / Lw)^(ln b / ln 0.5)).
float toneMapAdaptiveLogarithmic(float Ls, float Lw) {
    const float biasExponent = log(kDragoBias) / log(0.5);
    float interpolation = 2.0 + 8.0 * pow(Ls / Lw, biasExponent);
    return kDragoDisplayScale / log10(1.0 + Lw) * log(1.0 + Ls) / log(interpolation);
}

// Display luminance of a luminance operator.
float toneMapLuminance(int op, float Ls, float Lw) {
    if (op == TONE_MAP_EXP) return toneMapExp(Ls);
    if (op == TONE_MAP_REINHARD) return toneMapReinhard(Ls);
    if (op == TONE_MAP_REINHARD_MODIFIED) return toneMapReinhardModified(Ls, Lw);
    if (op == TONE_MAP_LOGARITHMIC) return toneMapLogarithmic(Ls, Lw);
    return toneMapAdaptiveLogarithmic(Ls, Lw);
}

// Radiance to the display-encoded colour in [0, 1]. `exposure` scales radiance to Reinhard's
// scaled luminance; `saturation` is the exponent s of Ld (C / L)^s that carries the colour over
// for the luminance operators (s = 1 keeps the chromaticity).
float3 toneMapToDisplay(float3 radiance, int op, float exposure, float Lw, float saturation) {
    float3 c = clamp(radiance, 0.0, kMaxRadiance);  // negative, infinite and NaN input made safe
    if (op == TONE_MAP_FILMIC_ALU) return saturate(toneMapFilmicAlu(exposure * c));
    float3 displayLinear;
    if (op == TONE_MAP_UNCHARTED_2) {
        displayLinear = toneMapUncharted2(exposure * c, Lw);
    } else {
        float L = relativeLuminance(c);
        float Ld = toneMapLuminance(op, exposure * L, Lw);
        displayLinear = L > 0.0 ? Ld * pow(c / L, saturation) : 0.0;
    }
    return linearToSrgb(saturate(displayLinear));
}

#endif
