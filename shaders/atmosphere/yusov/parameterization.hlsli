#ifndef FIRMAMENT_SCATTERING_PARAMETERIZATION_HLSLI
#define FIRMAMENT_SCATTERING_PARAMETERIZATION_HLSLI
// Yusov's non-linear parameterization of the 4D scattering tables (Yusov 2013, eq. 4-7) and
// its inverse. World parameters: altitude h, cosines of the view zenith (c_a), sun zenith
// (c_p) and sun-view (c_t) angles. Unit coordinates x in [0, 1] per dimension; the view
// zenith has two halves, below and above the horizon, each in [0, 1]. Texture coordinates put
// x = 0 and 1 on texel centres. The CPU twin: src/atmosphere/YusovParameterization.cpp.
#include "atmosphere/physics.hlsli"

static const float kViewZenithPower = 0.2;         // eq. 5
static const float kSunZenithMinCos = -0.1975;     // eq. 6: the sun below this is treated as here
static const float kSunZenithTanScale = 5.349135;  // tan(1.26 * 1.1)
static const float kSunViewPower = 1.5;            // eq. 7

// eq. 4: x_h = sqrt(h / H_atm).
float altitudeToUnit(AtmosphereConstants a, float h) { return sqrt(saturate(h / a.earth.y)); }
float unitToAltitude(AtmosphereConstants a, float x) { return x * x * a.earth.y; }

// eq. 5, one half each: above the horizon x = ((c_a - c_h) / (1 - c_h))^0.2, below it
// x = ((c_h - c_a) / (c_h + 1))^0.2.
float viewZenithToUnit(float cosView, float cosHorizonAngle, bool aboveHorizon) {
    float t = aboveHorizon ? (cosView - cosHorizonAngle) / (1.0 - cosHorizonAngle)
                           : (cosHorizonAngle - cosView) / (cosHorizonAngle + 1.0);
    return pow(saturate(t), kViewZenithPower);
}
float unitToViewZenith(float x, float cosHorizonAngle, bool aboveHorizon) {
    float t = pow(saturate(x), 1.0 / kViewZenithPower);
    return aboveHorizon ? cosHorizonAngle + t * (1.0 - cosHorizonAngle) : cosHorizonAngle - t * (cosHorizonAngle + 1.0);
}

// eq. 6 as in Bruneton's implementation, which Yusov 2013 cites:
// x = 0.5 (atan(max(c_p, -0.1975) tan(1.26 * 1.1)) / 1.1 + 0.74). (The document's printed form
// closes the bracket of atan before the tangent, which maps -0.1975 below zero.)
float sunZenithToUnit(float cosSun) {
    return saturate(0.5 * (atan(max(cosSun, kSunZenithMinCos) * kSunZenithTanScale) / 1.1 + 0.74));
}
float unitToSunZenith(float x) { return tan((2.0 * x - 0.74) * 1.1) / kSunZenithTanScale; }

// eq. 7 with gamma = theta / pi: x = 0.5 +- 0.5 |2 (gamma - 0.5)|^1.5.
float sunViewToUnit(float cosSunView) {
    float gamma = acos(clamp(cosSunView, -1.0, 1.0)) / kPi;
    float s = gamma >= 0.5 ? 1.0 : -1.0;
    return 0.5 + 0.5 * s * pow(abs(2.0 * (gamma - 0.5)), kSunViewPower);
}
float unitToSunView(float x) {
    float s = x >= 0.5 ? 1.0 : -1.0;
    float gamma = 0.5 + 0.5 * s * pow(abs(2.0 * (x - 0.5)), 1.0 / kSunViewPower);
    return cos(gamma * kPi);
}

// The cosine of the sun-view angle is bounded by the two zenith angles:
// cos(a + p) <= c_t <= cos(a - p).
float clampSunView(float cosView, float cosSun, float cosSunView) {
    float sines = sqrt(saturate(1.0 - cosView * cosView) * saturate(1.0 - cosSun * cosSun));
    return clamp(cosSunView, cosView * cosSun - sines, cosView * cosSun + sines);
}

// The world parameters of a texel of the packed 3D table (x: altitude, y: view zenith,
// z: sun-view slice * N_sunZenith + sun zenith), as unit coordinates at texel centres.
struct ScatteringSample {
    float altitude;
    float cosView;
    float cosSun;
    float cosSunView;
};

ScatteringSample texelToWorld(AtmosphereConstants a, uint3 texel) {
    float4 n = a.scatteringLutSize;
    uint halfView = (uint)n.y / 2;
    ScatteringSample s;
    s.altitude = unitToAltitude(a, texel.x / (n.x - 1.0));
    bool above = texel.y >= halfView;
    float viewUnit = (above ? texel.y - halfView : texel.y) / (halfView - 1.0);
    s.cosView = unitToViewZenith(viewUnit, cosHorizon(a, s.altitude), above);
    uint sunZenithTexel = texel.z % (uint)n.z, sunViewTexel = texel.z / (uint)n.z;
    s.cosSun = unitToSunZenith(sunZenithTexel / (n.z - 1.0));
    s.cosSunView = clampSunView(s.cosView, s.cosSun, unitToSunView(sunViewTexel / (n.w - 1.0)));
    return s;
}

// The ray a texel stands for, in a frame where the start is straight above the Earth's centre
// and the view turns in the x-y plane: the start (relative to the centre), the view and sun
// directions (the sun's x from cos(sun-view) = v . l), and which half of the view zenith axis
// the texel is in (the lower half: the ray ends on the ground).
struct TexelRay {
    float altitude;
    float3 start, viewDir, sunDir;
    bool belowHorizon;
};

TexelRay texelRay(AtmosphereConstants a, uint3 texel) {
    ScatteringSample s = texelToWorld(a, texel);
    TexelRay ray;
    ray.altitude = s.altitude;
    ray.start = float3(0.0, a.earth.x + s.altitude, 0.0);
    float sinView = sqrt(saturate(1.0 - s.cosView * s.cosView));
    ray.viewDir = float3(sinView, s.cosView, 0.0);
    float sunX = sinView > 1e-6 ? (s.cosSunView - s.cosView * s.cosSun) / sinView : 0.0;
    ray.sunDir = float3(sunX, s.cosSun, sqrt(saturate(1.0 - sunX * sunX - s.cosSun * s.cosSun)));
    ray.belowHorizon = texel.y < (uint)a.scatteringLutSize.y / 2;
    return ray;
}

// Unit coordinate x to the texture coordinate of the texel-centre grid of n texels.
float unitToTexture(float x, float n) { return (0.5 + x * (n - 1.0)) / n; }

// The view zenith's texture coordinate: the lower half [0.5/n, 0.5 - 0.5/n] below the horizon,
// the upper [0.5 + 0.5/n, 1 - 0.5/n] above, so that filtering never crosses the horizon.
float viewZenithToTexture(float x, float n, bool aboveHorizon) {
    return (aboveHorizon ? 0.5 : 0.0) + (0.5 + x * (n / 2.0 - 1.0)) / n;
}

#endif
