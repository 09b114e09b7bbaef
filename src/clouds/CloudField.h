#pragma once
// The cloud field's inputs: the constants the GPU's passes read (from the settings, the camera
// and the time) and the density map's texels (docs/clouds.md, "Cloudiness" and "Generation").
// The tests' twin of what the GPU generates from them is reference/CloudFieldTwin.h.
#include "clouds/CloudGrid.h"
#include "clouds/CloudStructures.h"

#include <glm/vec3.hpp>

#include <cstdint>
#include <vector>

namespace firmament {

struct CloudSettings;

// The density map tiles the world twice over, at two periods whose ratio is far from a simple
// fraction, so that their product does not repeat within the particle distance.
inline constexpr double kCoarseDensityPeriod = 97.0e3;  // m
inline constexpr double kFineDensityPeriod = 23.0e3;    // m
// The wind's speed per unit of the Speed control (m/s), and its direction (x, z).
inline constexpr double kWindPerSpeed = 50.0;
inline constexpr double kWindDirectionX = 0.8, kWindDirectionZ = 0.6;
// Generation writes at most this many particles; more are counted, not drawn.
inline constexpr unsigned kMaxCloudParticles = 1u << 20;

// Particles the grid can hold: a particle per cell and layer, at most kMaxCloudParticles.
unsigned cloudParticleCapacity(const CloudSettings& settings);

// The constants of the field's passes for a camera at `camera` (world m) at `seconds`.
gpu::CloudFieldConstants cloudFieldConstants(const CloudSettings& settings, glm::dvec3 camera, double seconds);

// Texel (x, y) of the density map of side `resolution`: fractal value noise that tiles, its
// octaves from 4 cells per side to a quarter of the resolution, stretched to fill [0, 1].
float cloudDensityTexel(int resolution, int x, int y);
std::vector<float> cloudDensityMap(int resolution);  // row by row

}  // namespace firmament
