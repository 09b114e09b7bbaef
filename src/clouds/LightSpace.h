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
// Multiply scattered light crosses the particles nearer the sun at this share of their
// extinction: the delta-M scaled medium (Wiscombe 1977), 1 - g^2 for the droplets' asymmetry g =
// 0.9, in which the scattering table's orders 2 and on were computed (shaders/clouds/
// particle_lighting.hlsli's kScaledExtinctionShare).
inline constexpr double kScaledExtinctionShare = 1.0 - 0.9 * 0.9;
// With "Opacity early exit", a particle's walk toward the sun stops once the light it shades with
// is below this: Yusov 2014 stops when the sun's transmittance e^(-tau) is; here the multiply
// scattered light's, e^(-(1 - g^2) tau), which falls far more slowly.
inline constexpr double kOpacityEarlyExit = 0.01;
// The sun's own transmittance e^(-tau) at which that happens: kOpacityEarlyExit^(1 / (1 - g^2)).
double sunTransmittanceAtEarlyExit();

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
// below it (sunTransmittanceAtEarlyExit() for the shading's walk).
double sunTransmittance(const std::vector<ModelParticle>& particles, size_t index, glm::dvec3 toSun, double earthRadius,
                        ParticleDensityMethod method, double earlyExit);

}  // namespace firmament
