// Tone mapping: the HDR frame to the display. The exposure is the manual 2^EV, or Reinhard's
// key / L_avg (times 2^EV) with the adapted log-average luminance from light_adaptation.hlsl;
// then one of the seven operators (tone_mapping_operators.hlsli) and sRGB encoding.
#include "common/fullscreen_triangle.hlsli"
#include "postfx/postfx_structures.hlsli"
#include "postfx/tone_mapping_operators.hlsli"

cbuffer ToneMappingBuffer : register(b0) {
    ToneMappingConstants toneMapping;
};

Texture2D<float4> hdrFrame : register(t0);
Texture2D<float> adaptedLogLuminance : register(t1);  // 1 x 1: ln of the adapted average

FullscreenVertex vs_main(uint vertexId : SV_VertexID) {
    return fullscreenTriangle(vertexId);
}

float4 ps_main(FullscreenVertex input) : SV_Target {
    float exposure = toneMapping.exposure.y;
    if (toneMapping.mode.y != 0) {
        float averageLuminance = exp(adaptedLogLuminance.Load(int3(0, 0, 0)));
        exposure *= toneMapping.exposure.x / averageLuminance;  // Reinhard et al. 2002, eq. 2
    }
    float3 radiance = hdrFrame.Load(int3(input.position.xy, 0)).rgb;
    float3 display = toneMapToDisplay(radiance, (int)toneMapping.mode.x, exposure, toneMapping.exposure.z, toneMapping.exposure.w);
    return float4(display, 1.0);
}
