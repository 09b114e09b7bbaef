#pragma once
// The particles' light occlusion on the CPU (Yusov 2014, "Computing light occlusion";
// docs/clouds.md, "Light occlusion"): the light-space grid's constants, and each particle's column
// along the sun (the optical depth nearer the sun and beyond it) by a walk over every particle,
// the twin of shaders/clouds/particle_opacity.hlsl (which walks only its tile's list).
#include "clouds/CloudField.h"
#include "clouds/CloudSettings.h"
#include "clouds/CloudStructures.h"

#include <glm/vec3.hpp>

#include <vector>

namespace firmament {

// The medium's extinction at density 1 (1/m): shaders/clouds/particle_shape.hlsli's kCloudExtinction.
inline constexpr double kCloudExtinction = 0.07;
// The share of the extinction that light scattered into the droplets' forward peak still sees:
// the delta-M scaled medium (Wiscombe 1977), 1 - g^2 for the droplets' asymmetry g = 0.9 (shaders/
// clouds/particle_lighting.hlsli's kScaledExtinctionShare): the direct sunlight at a particle is
// e^(-(1 - g^2) tau) of the optical depth tau nearer the sun.
inline constexpr double kScaledExtinctionShare = 1.0 - 0.9 * 0.9;
// With "Opacity early exit", a particle's walk along the sun stops once the column it has found
// (nearer the sun and beyond) is this thick: deck diffusion's light at a particle then changes by
// at most 6% however much thicker the column is (docs/clouds.md, "Light occlusion"), and the
// direct sunlight e^(-(1 - g^2) tau) is below 1e-21.
inline constexpr double kOpacityEarlyExitDepth = 256.0;

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

// Particle `index`'s column along the sun: the optical depths that the ray from its centre
// towards the sun crosses in the particles nearer the sun (`above`) and that the ray away from
// the sun crosses in those farther (`beyond`), walked from the sun's side in order, until, when
// `earlyExitDepth` > 0, their sum passes it.
struct SunColumn {
    double above = 0.0;
    double beyond = 0.0;
};
SunColumn sunColumn(const std::vector<ModelParticle>& particles, size_t index, glm::dvec3 toSun, double earthRadius, ParticleDensityMethod method,
                    double earlyExitDepth);

}  // namespace firmament
