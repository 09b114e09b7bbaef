// "Show sampling": every valid epipolar sample drawn over the frame as a square, six vertices
// from SV_VertexID alone: ray-marching samples as large red dots (5 pixels), interpolated ones
// as small green dots (1 pixel).
#include "lightshafts/epipolar_inputs.hlsli"

struct SampleDot {
    float4 position : SV_Position;
    float3 colour : COLOR0;
};

SampleDot vs_main(uint vertexId : SV_VertexID) {
    uint samples = epipolar.sampling.y;
    uint index = vertexId / 6, corner = vertexId % 6;
    int3 texel = int3(index % samples, index / samples, 0);
    float4 coordinates = sampleCoordinates.Load(texel);
    uint2 sources = interpolationSources.Load(texel);
    bool marched = sources.x == (uint)texel.x && sources.y == (uint)texel.x;
    static const float2 kCorners[6] = {float2(-1, -1), float2(1, -1), float2(-1, 1), float2(-1, 1), float2(1, -1), float2(1, 1)};
    float halfSize = marched ? 2.5 : 0.5;  // pixels
    SampleDot dot;
    dot.position = float4(coordinates.xy + kCorners[corner] * halfSize * 2.0 * frame.screen.zw, 0.0, 1.0);
    if (!validSample(coordinates)) dot.position = float4(2.0, 2.0, 0.0, 1.0);  // every corner there: nothing drawn
    dot.colour = frame.sunIrradiance.rgb * (marched ? float3(1.0, 0.0, 0.0) : float3(0.0, 1.0, 0.0));
    return dot;
}

float4 ps_main(SampleDot input) : SV_Target {
    return float4(input.colour, 1.0);
}
