// Epipolar sampling, pass 4: at every valid sample, the in-scattering along its view ray with
// nothing in shadow (the atmosphere's own render modes, atmosphere/yusov/view_ray.hlsli) and
// the transmittance T(C -> end). The refinement compares neighbours' in-scattering; the
// unwarping may take the extinction from here ("Extinction evaluation: epipolar").
#define FIRMAMENT_NO_SHADE_PIXEL 1
#include "lightshafts/epipolar_inputs.hlsli"
#include "atmosphere/yusov/shade_pixel.hlsli"

RWTexture2D<float4> coarseOut : register(u0);
RWTexture2D<float4> extinctionOut : register(u1);

[numthreads(SAMPLE_GROUP, 1, 1)]
void main(uint3 id : SV_DispatchThreadID) {
    if (id.x >= epipolar.sampling.y) return;
    float4 coordinates = sampleCoordinates.Load(int3(id.xy, 0));
    float3 light = 0.0, transmittance = 1.0;
    if (validSample(coordinates)) {
        PixelView v = pixelView(coordinates.xy, coordinates.w, 1.0);
        if (v.inAtmosphere) {
            light = scatteringAlongRay(v.ray, frame.directionToSun.xyz, lightShafts.mode.x, lightShafts.mode.z, (int)lightShafts.mode.y);
            transmittance = transmittanceTo(v.ray, v.ray.length);
        }
    }
    coarseOut[id.xy] = float4(light, 1.0);
    extinctionOut[id.xy] = float4(transmittance, 1.0);
}
