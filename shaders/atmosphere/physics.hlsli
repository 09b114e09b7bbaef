#ifndef FIRMAMENT_ATMOSPHERE_PHYSICS_HLSLI
#define FIRMAMENT_ATMOSPHERE_PHYSICS_HLSLI
// The atmosphere's physics on the GPU: geometry of the spherical Earth, particle densities,
// optical depth and phase functions. Positions are relative to the Earth's centre, in metres.
// The same equations in double precision: src/reference/ReferenceAtmosphere.cpp.
#include "atmosphere/atmosphere_structures.hlsli"

static const float kPi = 3.14159265358979;

// Distances along origin + t dir (|dir| = 1) to the sphere of `radius` about the centre:
// (near, far); both negative when the line misses it.
float2 raySphere(float3 origin, float3 dir, float radius) {
    float b = dot(origin, dir);
    float c = dot(origin, origin) - radius * radius;
    float discriminant = b * b - c;
    if (discriminant < 0.0) return float2(-1.0, -1.0);
    float root = sqrt(discriminant);
    return float2(-b - root, -b + root);
}

// Cosine of the zenith angle of the horizon seen from altitude h: rays with a smaller cosine
// hit the ground (Yusov 2013, after eq. 5: c_h = -sqrt(h (2R + h)) / (R + h)).
float cosHorizon(AtmosphereConstants a, float h) {
    h = max(h, 0.0);
    return -sqrt(h * (2.0 * a.earth.x + h)) / (a.earth.x + h);
}

// Relative densities at altitude h: x Rayleigh, y Mie (exp(-h / H)), z ozone (a tent of half
// width w about its peak, Bruneton 2017).
float3 particleDensity(AtmosphereConstants a, float h) {
    float2 exponential = exp(-h / a.scaleHeights.xy);
    float ozone = max(0.0, 1.0 - abs(h - a.ozoneLayer.x) / a.ozoneLayer.y);
    return float3(exponential, ozone);
}

// The altitude at distance t along the ray from radius r along the zenith cosine mu, by the law
// of cosines from rho^2 = r^2 - Rg^2 so that the metres near the ground survive single precision:
// h = (rho^2 + t^2 + 2 r mu t) / (r_t + Rg).
float altitudeAlongRay(AtmosphereConstants a, float r, float rho2, float mu, float t) {
    float above = rho2 + t * (t + 2.0 * r * mu);  // r_t^2 - Rg^2
    float rg = a.earth.x;
    return max(above / (sqrt(max(rg * rg + above, 0.0)) + rg), 0.0);
}

// Optical depth of a path whose net densities (density integrated over length) are given.
float3 opticalDepth(AtmosphereConstants a, float3 netDensity) {
    return a.rayleighScattering.rgb * netDensity.x + a.mieExtinction.rgb * netDensity.y + a.ozone.rgb * netDensity.z;
}

// Rayleigh phase function, normalised over the sphere: 3 / (16 pi) (1 + mu^2).
float rayleighPhase(float cosTheta) {
    return 3.0 / (16.0 * kPi) * (1.0 + cosTheta * cosTheta);
}

// Cornette-Shanks phase function for aerosols (Yusov 2013's sample; Bruneton 2008, eq. 4):
// 3 / (8 pi) (1 - g^2) (1 + mu^2) / ((2 + g^2) (1 + g^2 - 2 g mu)^1.5).
float miePhase(float cosTheta, float g) {
    float g2 = g * g;
    return 3.0 / (8.0 * kPi) * (1.0 - g2) * (1.0 + cosTheta * cosTheta) / ((2.0 + g2) * pow(max(1.0 + g2 - 2.0 * g * cosTheta, 1e-6), 1.5));
}

// Radiance scattered towards the viewer per unit length, per unit incident irradiance, at
// relative densities `density` for the scattering angle cos theta: the integrand of single
// scattering without its transmittances.
float3 scatteringCoefficient(AtmosphereConstants a, float3 density, float cosTheta) {
    return a.rayleighScattering.rgb * density.x * rayleighPhase(cosTheta) +
           a.mieScattering.rgb * density.y * miePhase(cosTheta, a.mieScattering.w);
}

#endif
