// Hillaire 2020's sky-view table (section 5.3), made each frame for the camera's altitude: at
// each texel, the view of the table's latitude and longitude (parameterization.hlsli: the
// latitude crowded about the true horizon, the longitude the azimuth from the sun's) marched in
// hillaire.skyView.z growing steps (march.hlsli) to the ground or the top, per unit sun irradiance. A camera above
// the atmosphere does not use it (render.hlsl marches each pixel); it is made at the top then.
#include "atmosphere/hillaire/camera_tables.hlsli"

RWTexture2D<float4> skyView : register(u0);

[numthreads(8, 8, 1)]
void main(uint3 id : SV_DispatchThreadID) {
    float2 size = hillaire.skyView.xy;
    if (id.x >= (uint)size.x || id.y >= (uint)size.y) return;
    HillaireCamera cam = hillaireCameraInAtmosphere(frame, atmosphere);
    float2 direction = hillaireSkyViewDirection(atmosphere, cam.r, (float2)id.xy / (size - 1.0));
    HillaireView v;
    v.r = cam.r;
    v.rho2 = cam.rho2;
    v.mu = direction.x;
    v.muS = dot(cam.up, frame.directionToSun.xyz);
    v.nu = v.mu * v.muS + sqrt(max(1.0 - v.mu * v.mu, 0.0)) * sqrt(max(1.0 - v.muS * v.muS, 0.0)) * direction.y;
    HillaireSegment s = marchView(v, 0.0, hillaireViewLength(atmosphere, v), (int)hillaire.skyView.z, true, hillaireEmptySegment());
    skyView[id.xy] = float4(s.radiance, 1.0);
}
