#pragma once
// The cloud field's inputs and its CPU model: the constants the GPU's passes read (from the
// settings, the camera and the time), the density map's texels, and the valid cells and particles
// the GPU generates from them, computed the same way in C++ (the tests' twin of
// shaders/clouds/cloud_field.hlsli; docs/clouds.md, "Cloudiness" and "Generation").
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

struct ModelParticle {
    glm::vec3 centre{0.0f};
    float horizontalRadius = 0.0f;
    float verticalRadius = 0.0f;
    float density = 0.0f;
    float azimuth = 0.0f;
    int ring = 0;
    unsigned cell = 0;  // index in the cell list
    int layer = 0;
};

struct CloudFieldModel {
    std::vector<unsigned> validCells;  // indices in the cell list, in list order
    // Per cell of the list: its coverage before it is clamped to 0..1 (not above 0: clear sky),
    // and how far it reaches: its middle's distance from the camera less its radius (m).
    std::vector<float> coverage;
    std::vector<float> reach;
    std::vector<ModelParticle> particles;
};

// What the GPU's valid-cell and generation passes produce for `constants`, `cells` (the packed
// list, CloudGrid order) and `map`, with the camera at `camera` on a planet of `earthRadius`.
CloudFieldModel modelCloudField(const gpu::CloudFieldConstants& constants, const std::vector<std::uint32_t>& cells, const std::vector<float>& map,
                                glm::vec3 camera, float earthRadius);

}  // namespace firmament
