#ifndef FIRMAMENT_BRUNETON_CAMERA_SEGMENT_HLSLI
#define FIRMAMENT_BRUNETON_CAMERA_SEGMENT_HLSLI
// Bruneton and Neyret 2008 between the camera and a point at a distance along a view ray, for a
// technique that draws something translucent in the air (the clouds): the light scattered into
// the stretch, S(x, v) - T(x -> x0) S(x0, v), per unit sun irradiance, and the transmittance
// T(x -> x0), as atmosphere/bruneton/render.hlsl computes them for geometry; from any point
// (brunetonSegment: the clouds' path-traced reference starts rays inside a cloud) or from the
// camera. A ray from above the atmosphere starts where it enters it. The includer declares
// cbuffers `frame`, `atmosphere` and `bruneton`.
#include "atmosphere/bruneton/lookup.hlsli"

struct CameraSegment {
    float3 light;          // in-scattered, per unit sun irradiance
    float3 transmittance;
};

CameraSegment brunetonSegment(float3 origin, float3 v, float3 s, float distance, Texture2D<float4> transmittanceLut, Texture3D<float4> inscatterLut,
                              SamplerState linearClamp) {
    CameraSegment segment;
    segment.light = 0.0;
    segment.transmittance = 1.0;
    float rg = atmosphere.earth.x, rt = atmosphere.earth.z;
    float3 x = origin + float3(0.0, rg, 0.0);
    float3 c = origin;
    float rho2 = dot(c.xz, c.xz) + c.y * (2.0 * rg + c.y);
    float h = rho2 / (length(x) + rg);
    float r = rg + h;
    float offset = 0.0;
    if (r > rt) {
        float2 top = raySphere(x, v, rt);
        if (top.y <= 0.0 || top.x <= 0.0) return segment;  // the ray misses the atmosphere
        offset = top.x;
        x += v * offset;
        h = atmosphere.earth.y - 1.0;
        r = rg + h;
        x *= r / length(x);
        rho2 = rho2At(atmosphere, h);
    }
    float mu = dot(x, v) / r, muS = dot(x, s) / r, nu = dot(v, s);
    bool toGround = mu < -sqrt(rho2) / r;
    float end = toGround ? distanceToGround(r, mu, rho2) : distanceToTop(atmosphere, r, mu, rho2);
    float t = min(distance - offset, end);
    if (t <= 0.0) return segment;
    segment.transmittance = transmittanceAlong(atmosphere, bruneton, transmittanceLut, linearClamp, r, mu, t);
    float3 x0 = x + v * t;
    float r0 = length(x0);
    float h0 = max((rho2 + t * (t + 2.0 * r * mu)) / (r0 + rg), 0.0);
    float4 fromCamera = lookUpInscatter(atmosphere, bruneton, inscatterLut, linearClamp, h, mu, muS, nu, toGround);
    float4 fromEnd = lookUpInscatter(atmosphere, bruneton, inscatterLut, linearClamp, h0, dot(x0, v) / r0, dot(x0, s) / r0, nu, toGround);
    float4 inscatter = max(fromCamera - segment.transmittance.rgbr * fromEnd, 0.0);
    segment.light = max(inscatter.rgb * rayleighPhase(nu) + mieFromRed(atmosphere, inscatter) * miePhase(nu, atmosphere.mieScattering.w), 0.0);
    return segment;
}

CameraSegment brunetonCameraSegment(float3 v, float3 s, float distance, Texture2D<float4> transmittanceLut, Texture3D<float4> inscatterLut,
                                    SamplerState linearClamp) {
    return brunetonSegment(frame.cameraPosition.xyz, v, s, distance, transmittanceLut, inscatterLut, linearClamp);
}

#endif
