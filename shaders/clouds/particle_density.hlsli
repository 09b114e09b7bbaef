#ifndef FIRMAMENT_PARTICLE_DENSITY_HLSLI
#define FIRMAMENT_PARTICLE_DENSITY_HLSLI
// The density inside a cloud particle, in its unit-sphere space (Yusov 2014, "3D noise
// generation"): a smooth radial fall-off perturbed by fractal 3D value noise, the same
// thresholded to 0 or 1, or a pyroclastic sphere whose radius the noise displaces. The CPU twin
// is src/clouds/ParticleDensity.cpp: change both together.
#include "common/hash.hlsli"

float particleLatticeValue(int3 c, uint octave) {
    return unitFromHash(hash32(asuint(c.x) ^ hash32(asuint(c.y) ^ hash32(asuint(c.z) ^ hash32(octave + 0x632be5abu)))));
}

// Perlin's quintic fade.
float3 particleFade(float3 t) { return t * t * t * (t * (t * 6.0 - 15.0) + 10.0); }

// Value noise: trilinear between the hashed values of the lattice cell's corners, 0..1.
float valueNoise3(float3 p, uint octave) {
    float3 f = floor(p);
    float3 t = particleFade(p - f);
    int3 c = int3(f);
    float v000 = particleLatticeValue(c, octave), v100 = particleLatticeValue(c + int3(1, 0, 0), octave);
    float v010 = particleLatticeValue(c + int3(0, 1, 0), octave), v110 = particleLatticeValue(c + int3(1, 1, 0), octave);
    float v001 = particleLatticeValue(c + int3(0, 0, 1), octave), v101 = particleLatticeValue(c + int3(1, 0, 1), octave);
    float v011 = particleLatticeValue(c + int3(0, 1, 1), octave), v111 = particleLatticeValue(c + int3(1, 1, 1), octave);
    float x00 = v000 + t.x * (v100 - v000), x10 = v010 + t.x * (v110 - v010);
    float x01 = v001 + t.x * (v101 - v001), x11 = v011 + t.x * (v111 - v011);
    float y0 = x00 + t.y * (x10 - x00), y1 = x01 + t.y * (x11 - x01);
    return y0 + t.z * (y1 - y0);
}

// Four octaves about 0, from 2 lattice cells per unit, each 1.9 times finer and 0.7 times weaker.
float particleNoise(float3 p) {
    float sum = 0.0, amplitude = 1.0, frequency = 2.0;
    for (uint o = 0; o < 4; ++o) {
        sum += (valueNoise3(p * frequency, o) - 0.5) * amplitude;
        frequency *= 1.9;
        amplitude *= 0.7;
    }
    return sum;
}

// The density methods (src/clouds/CloudSettings.h, ParticleDensityMethod).
static const uint kRadialNoise = 0, kThresholdedNoise = 1, kPyroclastic = 2;

// Density at p (|p| <= 1 inside the particle), 0..1. The fall-off (1 - r^2)^3 is 1 at the centre,
// 0 at the surface, flat at both.
float particleDensity(float3 p, uint method) {
    float r = length(p);
    if (r >= 1.0) return 0.0;
    float falloff = (1.0 - r * r) * (1.0 - r * r) * (1.0 - r * r);
    if (method == kPyroclastic) {
        float3 onSphere = r > 1e-6 ? p / r : float3(0.0, 1.0, 0.0);
        return r + 0.35 * particleNoise(onSphere) < 0.8 ? 1.0 : 0.0;
    }
    float perturbed = falloff + sqrt(falloff) * particleNoise(p);
    if (method == kThresholdedNoise) return perturbed > 0.1 ? 1.0 : 0.0;
    return saturate(perturbed);
}

#endif
