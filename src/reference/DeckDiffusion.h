#pragma once
// The light that diffuses through a deck of cloud (docs/clouds.md, "Deck diffusion"): the
// delta-Eddington solution (Joseph, Wiscombe and Weinman 1976) for a conservatively scattering
// slab lit by the sun along its normal. The particle renderer treats the column of particles
// along the sun's ray through a particle (the optical depth nearer the sun, its own, and the
// depth beyond it, from the light-space walk) as such a slab, and shades the particle with the
// diffuse radiance at its place in it. The CPU twin of clouds/particle_lighting.hlsli's
// deckDiffuseRadiance(). Beside it, the slab of the droplets' own medium solved by doubling and
// adding (src/clouds/DeckDiffusionTable.h), looked up as the GPU's sampler filters its table.
#include "clouds/DeckDiffusionTable.h"

namespace firmament {

// The diffuse radiance (1/sr, per unit sun irradiance across its rays) at optical depth `depth`
// of a slab of optical thickness `total`, both unscaled and along the sun's rays, travelling at
// cosine `mu` to the sun's light (1: straight away from the sun; -1: back towards it), in a
// medium of Henyey-Greenstein asymmetry `g`. Delta-M scaled (Wiscombe 1977): the forward peak
// f = g^2 of each scattering counts as unscattered, so the depths shrink by 1 - f and the
// asymmetry becomes g' = (g - f) / (1 - f); the direct beam e^(-(1 - f) tau) is not included.
// Eddington's radiance I = I0 + mu I1 solves, with k = 3 / (4 pi) and t the scaled depth,
//   dI1/dt = 3 e^(-t) / (4 pi),  dI0/dt = -(1 - g') I1 + 3 e^(-t) / (4 pi)
//   I1 = C1 - k e^(-t),  I0 = C0 - (1 - g') C1 t - k e^(-t)
// and Marshak's conditions (no diffuse light entering either face) give
//   C1 = k (5 - e^(-T)) / (4 + 3 (1 - g') T),  C0 = 5 k / 3 - 2 C1 / 3.
// Clamped at 0, where Eddington's linear radiance goes negative.
double deckDiffuseRadiance(double depth, double total, double mu, double g);

// The part of deckDiffuseRadiance() scattered once, under the same approximations (the scaled
// medium, Eddington's phase function 1 + 3 g' mu): the direct beam e^(-t') scattered at every
// depth and carried to t, downward (mu > 0) from the top, upward (m = -mu) from the bottom:
//   (1 + 3 g' mu) / (4 pi) (e^(-t) - e^(-t / mu)) / (1 - mu)            mu > 0 (t e^(-t) at mu = 1)
//   (1 + 3 g' mu) / (4 pi) (e^(-t) - e^(-T - (T - t) / m)) / (1 + m)    mu < 0
double deckSingleScattering(double depth, double total, double mu, double g);

// Deck diffusion's light scattered more than once: the renderer takes single scattering from
// the scattering table, in the particle (Nakajima and Tanaka 1988: replace the approximate
// solution's single scattering by an exact one).
double deckMultipleScattering(double depth, double total, double mu, double g);

// The table's coordinates in texels (node k at k), clamped to its nodes: x acos(-mu) / pi of the
// cosine mu between the light's travel and the sun's (node k at mu = -cos(pi k / (cosines - 1))),
// y the depth's share of the slab through acos(1 - 2 depth / total) / pi, z log2 of the
// thickness over the thinnest, times the nodes per octave. A slab thinner than the table's
// thinnest is looked up at the thinnest and scaled by (total / thinnest)^2, as light scattered
// twice grows in a thin slab (`scale`).
struct DeckDiffusionCoordinates {
    double x = 0.0, y = 0.0, z = 0.0, scale = 1.0;
};
DeckDiffusionCoordinates deckDiffusionCoordinates(const DeckDiffusionParameters& p, double depth, double total, double mu);

// Multiple scattering: Deck diffusion, solved slab: the radiance scattered more than once (1/sr,
// per unit sun irradiance across its rays) at optical depth `depth` of a slab of optical thickness
// `total`, both along the sun's rays, travelling at cosine `mu` to the sun's light (1: straight
// away from the sun; -1: back towards it), from the table (the CPU twin of
// clouds/particle_lighting.hlsli's solvedSlabMultipleScattering()).
double solvedSlabMultipleScattering(const DeckDiffusionTable& table, double depth, double total, double mu);

}  // namespace firmament
