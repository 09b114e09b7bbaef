#pragma once
// The particle's optical depth table on the CPU: its size, its parameterization and the mean
// density a texel holds (the twin of shaders/clouds/optical_depth_table.hlsli and
// precompute_optical_depth.hlsl; docs/clouds.md, "Optical depth table").
#include "clouds/CloudSettings.h"

#include <glm/vec3.hpp>
#include <glm/vec4.hpp>

#include <string>

namespace firmament {

struct OpticalDepthTableSize {
    int entryZenith = 32;        // N0
    int entryAzimuth = 64;       // N1
    int directionZenith = 32;    // N2
    int directionAzimuth = 64;   // N3
    int steps = 48;              // midpoints along a chord

    // The 3D texture: x entry azimuth, y entry zenith, z direction azimuth blocks of direction zenith.
    int width() const { return entryAzimuth; }
    int height() const { return entryZenith; }
    int depth() const { return directionZenith * directionAzimuth; }
    std::string describe() const;
};

struct TableRay {
    glm::vec3 entry;      // on the unit sphere
    glm::vec3 direction;  // unit, into the sphere
};

// The ray of table coordinates u (each 0..1) and back.
TableRay opticalDepthRay(glm::vec4 u);
glm::vec4 opticalDepthCoordinates(glm::vec3 entry, glm::vec3 direction);
// Texel (x, y, z) of the 3D texture: its coordinates (texel centres).
glm::vec4 opticalDepthTexelCoordinates(const OpticalDepthTableSize& size, int x, int y, int z);
// The mean density along the ray's chord through the unit sphere, at `steps` midpoints.
float meanChordDensity(const TableRay& ray, int steps, ParticleDensityMethod method);

}  // namespace firmament
