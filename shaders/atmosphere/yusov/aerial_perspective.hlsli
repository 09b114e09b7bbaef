#ifndef FIRMAMENT_AERIAL_PERSPECTIVE_HLSLI
#define FIRMAMENT_AERIAL_PERSPECTIVE_HLSLI
// What the atmosphere does to a view ray at render time: the light scattered into it between
// the camera and a point (or the end of the atmosphere), the transmittance over that stretch,
// and the sun's disc. Yusov 2013, eq. 8: L_in(C -> P) = L(C, v) - T(C -> P) L(P, v), with
// both look-ups on the same side of the horizon.
#include "atmosphere/yusov/single_scattering.hlsli"

// The part of a view ray inside the atmosphere: from a camera above the top, the ray starts
// where it enters. False when it misses the atmosphere altogether.
bool clipRayToAtmosphere(AtmosphereConstants a, inout float3 start, float3 viewDir, out float offset) {
    offset = 0.0;
    float radius = length(start);
    if (radius <= a.earth.z) return true;
    float2 top = raySphere(start, viewDir, a.earth.z);
    if (top.y <= 0.0) return false;
    offset = max(top.x, 0.0);
    start += viewDir * offset;
    start *= (a.earth.z - 1.0) / length(start);  // just inside, against rounding
    return true;
}

// The net density (Rayleigh, Mie, ozone) between two points of one view ray, from the net
// density table: the density to the top from the nearer point minus that from the farther,
// along the ray where it rises and against it where it falls (then the farther point sees the
// nearer one on its way up).
float3 netDensityBetween(AtmosphereConstants a, Texture2D<float4> netDensityLut, SamplerState linearClamp, float3 from, float3 to,
                         float3 viewDir) {
    float fromRadius = length(from), toRadius = length(to);
    float fromH = fromRadius - a.earth.x, toH = toRadius - a.earth.x;
    float3 netDensity;
    if (dot(from / fromRadius, viewDir) >= 0.0) {
        netDensity = netDensityToTop(a, netDensityLut, linearClamp, fromH, dot(from / fromRadius, viewDir)) -
                     netDensityToTop(a, netDensityLut, linearClamp, toH, dot(to / toRadius, viewDir));
    } else {
        netDensity = netDensityToTop(a, netDensityLut, linearClamp, toH, -dot(to / toRadius, viewDir)) -
                     netDensityToTop(a, netDensityLut, linearClamp, fromH, -dot(from / fromRadius, viewDir));
    }
    return max(netDensity, 0.0);
}

// Transmittance between two points of one view ray: exp(-optical depth of their net density).
float3 transmittanceBetween(AtmosphereConstants a, Texture2D<float4> netDensityLut, SamplerState linearClamp, float3 from, float3 to,
                            float3 viewDir) {
    return exp(-opticalDepth(a, netDensityBetween(a, netDensityLut, linearClamp, from, to, viewDir)));
}

#endif
