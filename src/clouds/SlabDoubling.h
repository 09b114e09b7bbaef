#pragma once
// The light inside a plane-parallel slab that scatters and absorbs nothing, lit by a parallel
// beam along its normal: the deck of cloud that deck diffusion stands for (docs/clouds.md, "Deck
// diffusion"; src/clouds/DeckDiffusionTable.h gives it the droplets' medium). Solved by doubling
// and adding (van de Hulst 1980; Hansen and Travis 1974) in the discrete ordinates of
// double-Gauss quadrature, Henyey-Greenstein scattering delta-M scaled (Wiscombe 1977) at the
// quadrature's own order, f = g^(2N): what is left of the forward peak past the quadrature's
// reach counts as unscattered. With the beam along the normal every radiance is symmetric about
// it, so only the azimuthal mean of the phase function enters:
//   p0(mu, mu') = sum_{l < 2N} (2l + 1) chi_l P_l(mu) P_l(mu'),  chi_l = (g^l - f) / (1 - f).
// Directions with zero weight (the viewing directions a table needs) ride along: they receive
// light and carry it, but scatter none into the others.
#include <vector>

namespace firmament {

class SlabDoubling {
public:
    // `gaussPerHemisphere` Gauss nodes on each half of [-1, 1]; `viewingCosines` in (0, 1] are
    // added as zero-weight directions (each hemisphere gets them all).
    SlabDoubling(double asymmetry, int gaussPerHemisphere, std::vector<double> viewingCosines = {});

    // Radiance per direction, per unit irradiance of the beam across its rays (1/sr), the beam
    // itself excluded. Index i is cosines()[i]: `down` travels with the beam (mu = +cosine),
    // `up` against it.
    struct Field {
        std::vector<double> down, up;
    };
    // The diffuse radiance at optical depth `depth` (from the lit face) of a slab of optical
    // thickness `total` (both before the scaling by 1 - f).
    Field diffuse(double depth, double total) const;
    // The part of it scattered once, exact for the scaled medium (the beam e^(-t') scattered at
    // every depth t' and carried to t, in scaled depths t):
    //   p'(mu) / (4 pi) (e^(-t) - e^(-t / mu)) / (1 - mu)              downward
    //   p'(-m) / (4 pi) (e^(-t) - e^(-T) e^(-(T - t) / m)) / (1 + m)   upward, m the cosine
    Field singleScattering(double depth, double total) const;
    // Reflected and diffusely transmitted flux, per unit flux in (the Gauss directions).
    double flux(const std::vector<double>& radiance) const;

    const std::vector<double>& cosines() const { return cosines_; }
    const std::vector<double>& weights() const { return weights_; }  // Gauss weights on [0, 1]; 0 for viewing directions
    double truncation() const { return truncation_; }                // f

    // p'(cosine): the scaled phase function, normalized to a mean of 1 over the sphere.
    double scaledPhase(double cosine) const;

    // A homogeneous layer of the medium, the same from both faces: R (down in, up out; by
    // symmetry also up in, down out), T (through, the unscattered light included on the
    // diagonal), and for the beam entering the top face, the diffuse light leaving the top
    // (`outTop`) and the bottom (`outBottom`); `beam` is the beam's transmittance.
    struct Layer {
        std::vector<double> reflection, transmission;  // n x n, row-major, n = cosines().size()
        std::vector<double> outTop, outBottom;
        double beam = 1.0;
    };
    // The layer of optical thickness `thickness` (before the scaling by 1 - f), by doubling from
    // 2^-30.
    Layer layer(double thickness) const;
    // The diffuse radiance between `above` (lit by the beam) and `below` (lit by what of the
    // beam crosses `above`): diffuse(t, T) is between(layer(t), layer(T - t)).
    Field between(const Layer& above, const Layer& below) const;

private:

    std::vector<double> cosines_, weights_;
    std::vector<double> moments_;  // chi_l, l < 2N
    double truncation_ = 0.0;
    std::vector<double> phaseSame_, phaseOpposite_;  // p0(mu_i, mu_j) and p0(-mu_i, mu_j), row-major
};

// The Gauss-Legendre nodes and weights of `n` points on [0, 1].
void gaussLegendreUnit(int n, std::vector<double>& nodes, std::vector<double>& weights);

}  // namespace firmament
