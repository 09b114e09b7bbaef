#pragma once
// The particles' light occlusion on the CPU (Yusov 2014, "Computing light occlusion";
// docs/clouds.md, "Light occlusion"): the light-space grid's constants, and each particle's sun
// transmittance by a walk over every particle nearer the sun, the twin of
// shaders/clouds/particle_opacity.hlsl (which walks only its tile's list).
#include "clouds/CloudField.h"
#include "clouds/CloudSettings.h"
#include "clouds/CloudStructures.h"

#include <glm/vec3.hpp>

#include <vector>

namespace firmament {

// The medium's extinction at density 1 (1/m): shaders/clouds/particle_shape.hlsli's kCloudExtinction.
inline constexpr double kCloudExtinction = 0.07;
// With "Opacity early exit", a particle's walk stops once its transmittance is below this (Yusov 2014).
inline constexpr double kOpacityEarlyExit = 0.01;

// Axes of a map seen from the sun: right and up across its rays, and the direction to it (unit).
struct SunFrame {
    glm::dvec3 right, up, sun;
};
SunFrame sunFrame(glm::dvec3 toSun);

// The map for a camera at `camera` and the sun along `toSun` (unit): centred over the camera at
// the layer's altitude, wide enough for the whole grid at any sun, `resolution` tiles a side.
gpu::CloudLightSpaceConstants lightSpaceConstants(const CloudSettings& settings, glm::dvec3 camera, glm::dvec3 toSun, unsigned nodeCapacity);

// The optical depth that the ray from `origin` along `toSun` crosses in particle `q` (0 when it
// misses), on a planet of `earthRadius` whose centre is below the origin of the world: the chord
// from the origin on, times the mean density along the whole chord (a `steps`-point march through
// the particle's density, turned by its azimuth), its density and the extinction.
double opticalDepthThrough(const ModelParticle& q, glm::dvec3 origin, glm::dvec3 toSun, double earthRadius, ParticleDensityMethod method,
                           int steps = 48);

// Particle `index`'s sun transmittance: the particles nearer the sun (along `toSun`) in order of
// nearness, their optical depths added until, when `earlyExit` > 0, the transmittance falls
// below it.
double sunTransmittance(const std::vector<ModelParticle>& particles, size_t index, glm::dvec3 toSun, double earthRadius,
                        ParticleDensityMethod method, double earlyExit);

}  // namespace firmament
