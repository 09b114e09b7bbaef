// Epipolar sampling, pass 3: every sample's place on the screen, evenly spaced from its slice's
// entry point to its exit point, with the depth buffer's value of the pixel under it and the
// camera-space depth of the sample's own ray ending there (where nothing was drawn, the ray
// itself decides between the ground and the sky, as the march will). Samples of invalid slices
// and samples off the screen are invalid: no later pass spends work on them.
#include "lightshafts/epipolar_inputs.hlsli"
#include "lightshafts/camera_space_depth.hlsli"

RWTexture2D<float4> samplesOut : register(u0);

[numthreads(SAMPLE_GROUP, 1, 1)]
void main(uint3 id : SV_DispatchThreadID) {
    if (id.x >= epipolar.sampling.y) return;
    float4 ends = sliceEnds.Load(int3(id.y, 0, 0));
    float4 coordinates = float4(kInvalidCoordinate, kInvalidCoordinate, kInvalidDepth, 0.0);
    if (validSlice(ends)) {
        float2 position = samplePosition(ends, id.x);
        if (onScreen(position)) {
            float depth = sceneDepth.Load(int3(pixelAt(position), 0));
            coordinates = float4(position, cameraSpaceDepth(position, depth), depth);
        }
    }
    samplesOut[id.xy] = coordinates;
}
