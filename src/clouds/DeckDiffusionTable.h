#pragma once
// Deck diffusion's table (docs/clouds.md, "Deck diffusion"): the light scattered more than once
// inside a slab of cloud lit by the sun along its normal, by the slab's optical thickness, the
// depth in it and the direction, per unit sun irradiance (1/sr). The medium is the droplets' own:
// Henyey-Greenstein g = 0.9, delta-M truncated (Wiscombe 1977) only at the solver's order, f =
// g^32 = 0.034, so the light that the forward peak carries a few tens of degrees off the sun's
// rays, order after order, is in it (the delta-Eddington medium, f = g^2, counts 81% of every
// scattering as unscattered and loses it). Orders 2 and on, solved by doubling and adding
// (src/clouds/SlabDoubling.h); the renderer adds the first order with the particle's single
// scattering (clouds/shade_particles.hlsl). Computed on the CPU by
// `firmament --generate-deck-diffusion` and shipped as media/clouds/deck-diffusion.exr. With
// Multiple scattering: Deck diffusion, solved slab (the default), the particle renderer shades
// each particle with it at the particle's place in its deck (clouds/particle_lighting.hlsli).
// src/reference/DeckDiffusion.h is the CPU twin of its look-up.
#include <filesystem>
#include <functional>
#include <string>
#include <vector>

namespace firmament {

struct DeckDiffusionParameters {
    double asymmetry = 0.9;       // Henyey-Greenstein g of the droplets (the scattering table's)
    int gaussPerHemisphere = 16;  // the solver's streams: 32 (its truncation, g^32, is 0.034)
    // Optical thicknesses thinnest * 2^(k / perOctave), k < thicknesses: 1/16 .. 1024.
    double thinnest = 1.0 / 16.0;
    int thicknessesPerOctave = 3;
    int thicknesses = 43;
    // Depths: the share s = (1 - cos(pi k / (depths - 1))) / 2 of the thickness, closer together
    // near both faces, where the light changes fastest.
    int depths = 32;
    // Directions: the cosine mu = -cos(pi k / (cosines - 1)) between the light's travel and the
    // sun's (1: straight away from the sun), even steps in angle, 5.8 degrees apart, so that the
    // light near the sun's rays, which changes fastest, has nodes as close as anywhere. An even
    // count, so that no node lies in the plane of the slab.
    int cosines = 32;

    double thickness(int k) const;
    double depthShare(int k) const;
    double cosine(int k) const;
    std::string describe() const;  // everything that shapes the table (its key)
};

struct DeckDiffusionTable {
    DeckDiffusionParameters parameters;
    // x cosine, y depth, z thickness (the GPU's 3D texture's order).
    std::vector<float> multiple;

    size_t index(int cosine, int depth, int thickness) const {
        return (static_cast<size_t>(thickness) * parameters.depths + depth) * parameters.cosines + cosine;
    }
};

// The light scattered more than once at one point, from the solver with `gaussPerHemisphere`
// streams a hemisphere (the table's look-up is src/reference/DeckDiffusion.h).
double solveDeckMultipleScattering(const DeckDiffusionParameters& p, int gaussPerHemisphere, double depth, double total, double mu);

// The whole table; `progress` (0..1) is called after each thickness. `onlyThickness` >= 0
// computes that thickness alone (the others stay zero).
DeckDiffusionTable computeDeckDiffusion(const DeckDiffusionParameters& p, const std::function<void(double)>& progress = {},
                                        int onlyThickness = -1);

// The table's file: R the light, a tile of cosine x depth per thickness, one above the other;
// its header holds the key and says what it is. Reading throws Error naming the file and the
// problem (missing, not made for `expected`: run tools/generate-cloud-scattering).
std::string deckDiffusionKey(const DeckDiffusionParameters& p);
void writeDeckDiffusion(const std::filesystem::path& path, const DeckDiffusionTable& table);
DeckDiffusionTable readDeckDiffusion(const std::filesystem::path& path, const DeckDiffusionParameters& expected);

}  // namespace firmament
