#ifndef FIRMAMENT_POSTFX_STRUCTURES_HLSLI
#define FIRMAMENT_POSTFX_STRUCTURES_HLSLI
// The HDR pipeline's constant-buffer structures, one definition read by HLSL and C++
// (src/postfx/PostfxStructures.h), under the rules of common/shared_structures.hlsli.
#include "common/shared_structures.hlsli"

// postfx/log_luminance.hlsl and postfx/light_adaptation.hlsl
struct SceneLuminanceConstants {
    float4 source;      // xy: size of the HDR frame in pixels; zw: unused
    float4 adaptation;  // x: weight of the measured value, 1 - exp(-dt / tau) (1: take it as
                        // it is); yzw: unused
    float4 histogram;   // x: the low percentile, y: the high one (shares of the pixels that are
                        // not black); zw: unused
};
FIRMAMENT_CONSTANT_BUFFER(SceneLuminanceConstants);

// postfx/tone_mapping.hlsl
struct ToneMappingConstants {
    uint4 mode;       // x: operator (ToneMapOperator's order); y: 1 = auto exposure from the adapted
                      // log-average luminance, 0 = manual; zw: unused
    float4 exposure;  // x: middle grey (key); y: 2^EV (the manual exposure, or the compensation on
                      // top of auto exposure); z: white point Lw; w: luminance saturation
};
FIRMAMENT_CONSTANT_BUFFER(ToneMappingConstants);

#endif
