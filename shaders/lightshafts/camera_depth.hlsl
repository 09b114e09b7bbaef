// Epipolar sampling, pass 1: the camera-space depth of every pixel (m along the camera's
// forward axis) from the reversed-Z depth buffer; kSkyDepth where nothing was drawn. The
// refinement and the unwarping compare depths in this form.
#include "lightshafts/epipolar_inputs.hlsli"

RWTexture2D<float> cameraDepthOut : register(u0);

[numthreads(PIXEL_GROUP, PIXEL_GROUP, 1)]
void main(uint3 id : SV_DispatchThreadID) {
    float2 pixel = (float2)id.xy;
    if (any(pixel >= frame.screen.xy)) return;
    float depth = sceneDepth.Load(int3(id.xy, 0));
    float z = kSkyDepth;
    if (depth > 0.0) {
        float2 uv = (pixel + 0.5) * frame.screen.zw;
        float4 world = mul(frame.inverseViewProjection, float4(uv.x * 2.0 - 1.0, 1.0 - uv.y * 2.0, depth, 1.0));
        z = dot(world.xyz / world.w - frame.cameraPosition.xyz, epipolar.cameraForward.xyz);
    }
    cameraDepthOut[id.xy] = z;
}
