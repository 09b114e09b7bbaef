// Hillaire 2020's aerial-perspective volume (section 5.4), made each frame: froxels of the
// camera's frustum, N x N columns across the screen (column i's view through the screen's
// u = (i + 0.5) / N) by N slices in depth, slice k at the distance k D / (N - 1) (slice 0 the
// camera itself). Each column is one march, hillaire.aerialPerspective.z steps a slice, that
// writes the in-scattered radiance per unit sun irradiance and the transmittance gathered up
// to each slice. The paper stores the transmittance's mean in alpha; Firmament keeps its
// colour, in a second volume.
#include "atmosphere/hillaire/camera_tables.hlsli"

RWTexture3D<float4> inscattering : register(u0);
RWTexture3D<float4> transmittance : register(u1);

[numthreads(8, 8, 1)]
void main(uint3 id : SV_DispatchThreadID) {
    uint n = (uint)hillaire.aerialPerspective.x;
    if (id.x >= n || id.y >= n) return;
    float2 uv = (id.xy + 0.5) / n;
    float4 farPoint = mul(frame.clipToDirection, float4(uv.x * 2.0 - 1.0, 1.0 - uv.y * 2.0, 1.0, 1.0));
    float3 direction = normalize(farPoint.xyz / farPoint.w);
    HillaireCamera cam = hillaireCameraInAtmosphere(frame, atmosphere);
    HillaireView v = hillaireViewAlong(cam.r, cam.rho2, cam.up, direction, frame.directionToSun.xyz);
    float sliceDepth = hillaire.aerialPerspective.y / (n - 1);
    int steps = (int)hillaire.aerialPerspective.z;
    HillaireSegment s = hillaireEmptySegment();
    inscattering[uint3(id.xy, 0)] = float4(s.radiance, 1.0);
    transmittance[uint3(id.xy, 0)] = float4(s.transmittance, 1.0);
    for (uint k = 1; k < n; ++k) {
        s = marchView(v, (k - 1) * sliceDepth, k * sliceDepth, steps, false, s);
        inscattering[uint3(id.xy, k)] = float4(s.radiance, 1.0);
        transmittance[uint3(id.xy, k)] = float4(s.transmittance, 1.0);
    }
}
