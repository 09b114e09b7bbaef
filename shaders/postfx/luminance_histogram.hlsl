// Scene luminance with Metering: Histogram (docs/tonemapping.md, "Metering"): instead of the mip
// chain's mean of every texel, a histogram of the 64 x 64 texels of ln(delta + L) (each already
// the mean over its part of the frame, log_luminance.hlsl), black texels left out, and the mean
// of the values between two percentiles of the rest: the darkest tenth and the brightest 2% by
// default. Space around the Earth, the sun's disc and glints then leave the exposure alone. One
// group of 256 threads, 16 texels each; the bins count texels and sum their values in fixed
// point (1/256) in group-shared memory; the first thread walks the bins. The CPU twin is
// tonemap::histogramMeanLogLuminance (src/postfx/ToneMappingCurves.h).
#include "postfx/postfx_structures.hlsli"
#include "postfx/tone_mapping_constants.hlsli"

cbuffer SceneLuminanceBuffer : register(b0) {
    SceneLuminanceConstants sceneLuminance;
};

Texture2D<float> logLuminance : register(t0);  // level 0: 64 x 64 of ln(delta + L)
RWTexture2D<float> measured : register(u0);    // 1 x 1: the metered ln(delta + L)

static const uint kTexels = 64 * 64;
static const float kFixedPoint = 256.0;

groupshared uint counts[kHistogramBins];
groupshared uint sums[kHistogramBins];  // (value - kHistogramLowestLog) x 256, summed

[numthreads(256, 1, 1)]
void main(uint3 thread : SV_GroupThreadID) {
    uint t = thread.x;
    if (t < (uint)kHistogramBins) {
        counts[t] = 0;
        sums[t] = 0;
    }
    GroupMemoryBarrierWithGroupSync();
    float black = log(kLogLuminanceDelta + kBlackLuminance);
    float range = kHistogramHighestLog - kHistogramLowestLog;
    [unroll] for (uint k = 0; k < kTexels / 256; ++k) {
        uint i = t * (kTexels / 256) + k;
        float value = logLuminance.Load(int3(i % 64, i / 64, 0));
        if (!(value > black)) continue;
        float x = saturate((value - kHistogramLowestLog) / range);
        uint bin = min((uint)(x * kHistogramBins), (uint)kHistogramBins - 1);
        InterlockedAdd(counts[bin], 1u);
        InterlockedAdd(sums[bin], (uint)(x * range * kFixedPoint + 0.5));
    }
    GroupMemoryBarrierWithGroupSync();
    if (t != 0) return;
    float total = 0.0, all = 0.0;
    for (uint b = 0; b < (uint)kHistogramBins; ++b) {
        total += (float)counts[b];
        all += (float)sums[b];
    }
    float from = sceneLuminance.histogram.x * total, to = sceneLuminance.histogram.y * total;
    float below = 0.0, sum = 0.0, weight = 0.0;
    for (uint c = 0; c < (uint)kHistogramBins; ++c) {
        float n = (float)counts[c];
        if (n == 0.0) continue;
        float overlap = max(0.0, min(below + n, to) - max(below, from));
        sum += overlap * ((float)sums[c] / (kFixedPoint * n) + kHistogramLowestLog);
        weight += overlap;
        below += n;
    }
    // One store of a computed value: Wine's GLSL translation fails on a typed store of a constant.
    float result = weight > 0.0 ? sum / weight : all / (kFixedPoint * max(total, 1.0)) + kHistogramLowestLog;
    if (total == 0.0) result = log(kLogLuminanceDelta) + sceneLuminance.histogram.z;  // nothing lit (z is 0: keeps it a register)
    measured[uint2(0, 0)] = result;
}
