#pragma once
// The density inside a cloud particle, in its unit-sphere space: the CPU twin of
// shaders/clouds/particle_density.hlsli (Yusov 2014, "3D noise generation").
#include "clouds/CloudSettings.h"

#include <glm/vec3.hpp>

namespace firmament {

// Value noise at p for an octave, 0..1: trilinear between hashed lattice values.
float valueNoise3(glm::vec3 p, unsigned octave);
// Four octaves about 0: 2 lattice cells per unit, each octave 1.9 times finer and 0.7 times weaker.
float particleNoise(glm::vec3 p);
// The density at p, 0..1 (0 outside the unit sphere).
float particleDensity(glm::vec3 p, ParticleDensityMethod method);

}  // namespace firmament
