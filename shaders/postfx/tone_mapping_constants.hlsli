#ifndef FIRMAMENT_TONE_MAPPING_CONSTANTS_HLSLI
#define FIRMAMENT_TONE_MAPPING_CONSTANTS_HLSLI
// Constants of the luminance measurement and of the tone mapping operators, in one place:
// HLSL includes this file and so does C++ (src/postfx/ToneMappingCurves.h, the CPU
// reference), where `static const float` means the same (hence the f suffixes: MSVC warns
// about double literals narrowed to float). docs/tonemapping.md cites each.

// Relative luminance of linear Rec. 709 / sRGB primaries (ITU-R BT.709).
static const float kLuminanceRed = 0.2126f;
static const float kLuminanceGreen = 0.7152f;
static const float kLuminanceBlue = 0.0722f;

// Offset inside the logarithm of the log-average luminance, exp(mean(ln(delta + L)))
// (Reinhard et al. 2002, eq. 1): keeps black pixels from sending the average to zero.
static const float kLogLuminanceDelta = 1.0e-4f;
// Histogram metering: the bins' range of ln(delta + L), their count, and the luminance below
// which a pixel is black (space, or nothing drawn) and left out.
static const float kHistogramLowestLog = -12.0f;
static const float kHistogramHighestLog = 10.0f;
static const int kHistogramBins = 128;
static const float kBlackLuminance = 1.0e-6f;

// The largest finite half float: the HDR frame (RGBA16F) holds nothing brighter, and the
// operators clamp their input to [0, this] so that negative or infinite input cannot make
// a NaN.
static const float kMaxRadiance = 65504.0f;

// Hable's filmic curve (Uncharted 2, GDC 2010): shoulder strength A, linear strength B,
// linear angle C, toe strength D, toe numerator E, toe denominator F, and the exposure bias
// he applies before the curve.
static const float kHableShoulderStrength = 0.15f;
static const float kHableLinearStrength = 0.50f;
static const float kHableLinearAngle = 0.10f;
static const float kHableToeStrength = 0.20f;
static const float kHableToeNumerator = 0.02f;
static const float kHableToeDenominator = 0.30f;
static const float kHableExposureBias = 2.0f;

// Hable's ALU approximation of the Hejl / Burgess-Dawson filmic curve: its output already
// contains the display's gamma. x = max(0, c - offset); y = x (a x + b) / (x (a x + c) + d).
static const float kFilmicAluOffset = 0.004f;
static const float kFilmicAluA = 6.2f;
static const float kFilmicAluB = 0.5f;
static const float kFilmicAluC = 1.7f;
static const float kFilmicAluD = 0.06f;

// Drago et al. 2003: the bias parameter b of the adaptive logarithmic mapping (0.85 is the
// paper's recommended value) and the display's maximum luminance scale, L_dmax / 100.
static const float kDragoBias = 0.85f;
static const float kDragoDisplayScale = 1.0f;

#endif
