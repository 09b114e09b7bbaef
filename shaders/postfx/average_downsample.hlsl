// Scene luminance, step 2 of 3: one mip level of the 64 x 64 log-luminance target from the
// level above it, each texel the mean of the four beneath it. Run six times, from 32 x 32 to
// 1 x 1; the last level holds the mean of ln(delta + L) over the whole frame.
#include "common/fullscreen_triangle.hlsli"

Texture2D<float> finerLevel : register(t0);  // a view of the level above only

FullscreenVertex vs_main(uint vertexId : SV_VertexID) {
    return fullscreenTriangle(vertexId);
}

float ps_main(FullscreenVertex input) : SV_Target {
    int2 finer = int2(input.position.xy) * 2;
    return 0.25 * (finerLevel.Load(int3(finer, 0)) + finerLevel.Load(int3(finer + int2(1, 0), 0)) +
                   finerLevel.Load(int3(finer + int2(0, 1), 0)) + finerLevel.Load(int3(finer + int2(1, 1), 0)));
}
