// Epipolar sampling, pass 1: the camera-space depth of every pixel (lightshafts/
// camera_space_depth.hlsli) from the reversed-Z depth buffer. The refinement and the unwarping
// compare depths in this form.
#include "lightshafts/epipolar_inputs.hlsli"
#include "lightshafts/camera_space_depth.hlsli"

RWTexture2D<float> cameraDepthOut : register(u0);

[numthreads(PIXEL_GROUP, PIXEL_GROUP, 1)]
void main(uint3 id : SV_DispatchThreadID) {
    float2 pixel = (float2)id.xy;
    if (any(pixel >= frame.screen.xy)) return;
    float2 uv = (pixel + 0.5) * frame.screen.zw;
    cameraDepthOut[id.xy] = cameraSpaceDepth(float2(uv.x * 2.0 - 1.0, 1.0 - uv.y * 2.0), sceneDepth.Load(int3(id.xy, 0)));
}
