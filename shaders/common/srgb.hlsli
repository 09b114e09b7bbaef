#ifndef FIRMAMENT_SRGB_HLSLI
#define FIRMAMENT_SRGB_HLSLI
// The sRGB transfer function (IEC 61966-2-1): linear [0,1] to encoded [0,1].

float3 linearToSrgb(float3 linearColor) {
    float3 low = linearColor * 12.92;
    float3 high = 1.055 * pow(max(linearColor, 0.0031308), 1.0 / 2.4) - 0.055;
    return lerp(high, low, step(linearColor, 0.0031308));
}

#endif
