#pragma once
// The tests' twin of the particles' light occlusion (shaders/clouds/particle_opacity.hlsl, which
// walks only its tile's list; Yusov 2014, "Computing light occlusion"; docs/clouds.md, "Light
// occlusion"): each particle's column along the sun, by a walk over every particle.
#include "clouds/CloudSettings.h"
#include "reference/CloudFieldTwin.h"

#include <glm/vec3.hpp>

#include <vector>

namespace firmament {

// The stretch [start, end] (metres from the origin, start >= 0) of the ray from `origin` along
// `toSun` inside particle `q`, and the optical depth it crosses there; all 0 when it misses.
struct Chord {
    double start = 0.0;
    double end = 0.0;
    double opticalDepth = 0.0;
};
// On a planet of `earthRadius` whose centre is below the origin of the world: the chord from the
// origin on, times the mean density along the whole chord (a `steps`-point march through the
// particle's density, turned by its azimuth), its density and the extinction.
Chord chordThrough(const ModelParticle& q, glm::dvec3 origin, glm::dvec3 toSun, double earthRadius, ParticleDensityMethod method, int steps = 48);
// Its optical depth alone.
double opticalDepthThrough(const ModelParticle& q, glm::dvec3 origin, glm::dvec3 toSun, double earthRadius, ParticleDensityMethod method,
                           int steps = 48);

// Particle `index`'s column along the sun: the optical depths that the ray from its centre
// towards the sun crosses in the particles nearer the sun (`above`) and that the ray away from
// the sun crosses in those farther (`beyond`), walked from the sun's side in order, until, when
// `earlyExitDepth` > 0, their sum passes it. Of each, the part in the particle's deck
// (`deckAbove`, `deckBeyond`): the chords of the particles walked whose union, with the
// particle's own chord, reaches them from the particle without a gap of clear air longer than
// kDeckGapShare (clouds/LightSpace.h) of the particle's half-width across the ray.
struct SunColumn {
    double above = 0.0;
    double beyond = 0.0;
    double deckAbove = 0.0;
    double deckBeyond = 0.0;
};
SunColumn sunColumn(const std::vector<ModelParticle>& particles, size_t index, glm::dvec3 toSun, double earthRadius, ParticleDensityMethod method,
                    double earlyExitDepth);

}  // namespace firmament
