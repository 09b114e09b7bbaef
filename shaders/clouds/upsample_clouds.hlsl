// The clouds rendered at low resolution, brought to the frame (docs/clouds.md, "Low-resolution
// rendering"; Yusov 2014, "Low-resolution rendering"): a bilateral upsample by depth. Each
// full-resolution pixel takes the four low-resolution samples around it, each weighted by its
// bilinear weight over (epsilon + the relative difference between its depth and the pixel's), so
// that across a terrain or sky edge the samples of the other side count for almost nothing and
// the edge stays sharp. The low-resolution target holds the clouds' premultiplied light and, in
// alpha, the transmittance to what is behind them; blended over the frame as
// C = L_clouds + T C_scene (premultiplied alpha, the source alpha 1 - T).
#include "clouds/cloud_structures.hlsli"
#include "common/fullscreen_triangle.hlsli"

cbuffer UpsampleBuffer : register(b0) { CloudUpsampleConstants upsample; };
Texture2D<float4> lowClouds : register(t0);
Texture2D<float> lowDepth : register(t1);
Texture2D<float> sceneDepth : register(t2);  // full resolution

// Depths are reversed and proportional to 1 / distance, so their relative difference is the
// distances' (0 for two sky samples, 1 between the sky and anything).
static const float kDepthEpsilon = 1e-3;

FullscreenVertex vs_main(uint vertexId : SV_VertexID) { return fullscreenTriangle(vertexId); }

float4 ps_main(FullscreenVertex input) : SV_Target {
    float depth = sceneDepth.Load(int3(input.position.xy, 0));
    int2 lowSize = int2(upsample.sizes.yz);
    float2 q = input.position.xy / float(upsample.sizes.x) - 0.5;
    int2 base = int2(floor(q));
    float2 f = q - float2(base);
    float4 sum = 0.0;
    float weights = 0.0;
    for (int k = 0; k < 4; ++k) {
        int2 offset = int2(k & 1, k >> 1);
        int2 texel = clamp(base + offset, int2(0, 0), lowSize - 1);
        float bilinear = (offset.x == 1 ? f.x : 1.0 - f.x) * (offset.y == 1 ? f.y : 1.0 - f.y);
        float sampleDepth = lowDepth.Load(int3(texel, 0));
        float difference = abs(sampleDepth - depth) / max(max(sampleDepth, depth), 1e-30);
        float w = bilinear / (kDepthEpsilon + difference);
        sum += w * lowClouds.Load(int3(texel, 0));
        weights += w;
    }
    float4 clouds = sum / weights;
    return float4(clouds.rgb, 1.0 - clouds.a);
}
