#pragma once
// The light space of the particles' light occlusion (Yusov 2014, "Computing light occlusion";
// docs/clouds.md, "Light occlusion"): the medium's extinction and its delta-M share, the sun's
// frame, and the light-space grid's constants. The tests' twin of the walk along the sun is
// reference/SunColumnTwin.h.
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
// A particle's deck along the sun (deck diffusion's slab) bridges gaps of clear air up to this
// share of the particle's half-width across the sun's ray; a longer gap ends it (shaders/clouds/
// deck_chords.hlsli's kDeckGapShare; chosen by measurement against the path-traced reference,
// docs/clouds.md, "Deck diffusion").
inline constexpr double kDeckGapShare = 0.25;

// Axes of a map seen from the sun: right and up across its rays, and the direction to it (unit).
struct SunFrame {
    glm::dvec3 right, up, sun;
};
SunFrame sunFrame(glm::dvec3 toSun);

// The map for a camera at `camera` and the sun along `toSun` (unit): centred over the camera at
// the layer's altitude, wide enough for the whole grid at any sun, `resolution` tiles a side.
gpu::CloudLightSpaceConstants lightSpaceConstants(const CloudSettings& settings, glm::dvec3 camera, glm::dvec3 toSun, unsigned nodeCapacity);

}  // namespace firmament
