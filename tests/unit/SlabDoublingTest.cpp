// The plane-parallel slab solver behind deck diffusion (src/clouds/SlabDoubling.h): energy kept
// at every depth, single scattering where the slab is thin, and Chandrasekhar's closed form for
// a semi-infinite slab that scatters isotropically.
#include "clouds/SlabDoubling.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <vector>

namespace firmament {
namespace {

constexpr double kPi = 3.14159265358979323846;

// A medium that absorbs nothing keeps the net flux along the normal: at every depth the beam,
// the diffuse light down less the diffuse light up, is 1 less what the top reflects; and at the
// bottom what is transmitted and reflected sums to the light in.
TEST(SlabDoubling, TheNetFluxIsTheSameAtEveryDepth) {
    const SlabDoubling slab(0.9, 16, {0.3, 1.0});
    for (const double total : {0.5, 16.0, 256.0}) {
        const double reflected = slab.flux(slab.diffuse(0.0, total).up);
        const double scaled = 1.0 - slab.truncation();
        for (const double share : {0.0, 0.1, 0.5, 0.93, 1.0}) {
            const double depth = share * total;
            const SlabDoubling::Field field = slab.diffuse(depth, total);
            const double net = std::exp(-scaled * depth) + slab.flux(field.down) - slab.flux(field.up);
            EXPECT_NEAR(net, 1.0 - reflected, 2e-5) << "thickness " << total << ", depth " << depth;
        }
        const double transmitted = slab.flux(slab.diffuse(total, total).down) + std::exp(-scaled * total);
        std::printf("thickness %.1f: reflected %.6f, transmitted %.6f (the beam %.3g), sum %.9f\n", total, reflected, transmitted,
                    std::exp(-scaled * total), reflected + transmitted);
        EXPECT_NEAR(reflected + transmitted, 1.0, 2e-5) << total;
        EXPECT_GT(reflected, 0.0);
    }
}

// Optically thin, the diffuse light is the light scattered once: the solver's field against its
// own closed form of single scattering, within the share that scatters twice (of the order of
// the optical path, here at most 0.001 / 0.3, times the ratio of the light scattered twice to once:
// large against the sun, where scattering once sends little), at the directions not near grazing.
TEST(SlabDoubling, AThinSlabScattersOnce) {
    const SlabDoubling slab(0.9, 16, {0.05, 0.5, 1.0});
    const double total = 0.001;
    for (const double share : {0.0, 0.5, 1.0}) {
        const SlabDoubling::Field field = slab.diffuse(share * total, total), once = slab.singleScattering(share * total, total);
        for (size_t i = 0; i < field.down.size(); ++i) {
            if (slab.cosines()[i] < 0.3) continue;
            if (once.down[i] > 1e-6) {
                EXPECT_NEAR(field.down[i] / once.down[i], 1.0, 0.02) << share << ", " << slab.cosines()[i];
            }
            if (once.up[i] > 1e-6) {
                EXPECT_NEAR(field.up[i] / once.up[i], 1.0, 0.02) << share << ", " << slab.cosines()[i];
            }
        }
    }
}

// Chandrasekhar's H-function for conservative isotropic scattering, from his integral equation
// in the form 1 / H(mu) = 1/2 integral_0^1 mu' H(mu') / (mu + mu') dmu', iterated on a fine Gauss
// grid until it stops changing: independent of the doubling. Each step takes the geometric mean
// of H and the equation's new H, since the equation alone maps c H to H / c and would swing
// between the two for ever.
class ChandrasekharH {
public:
    ChandrasekharH() {
        gaussLegendreUnit(400, nodes_, weights_);
        h_.assign(nodes_.size(), 1.0);
        for (int iteration = 0; iteration < 500; ++iteration) {
            std::vector<double> next(nodes_.size());
            double change = 0.0;
            for (size_t i = 0; i < nodes_.size(); ++i) {
                next[i] = std::sqrt(h_[i] * (*this)(nodes_[i]));
                change = std::max(change, std::abs(next[i] - h_[i]));
            }
            h_ = next;
            if (change < 1e-13) break;
        }
    }
    double operator()(double mu) const {
        double sum = 0.0;
        for (size_t j = 0; j < nodes_.size(); ++j) sum += 0.5 * weights_[j] * nodes_[j] * h_[j] / (mu + nodes_[j]);
        return 1.0 / sum;
    }

private:
    std::vector<double> nodes_, weights_, h_;
};

// A semi-infinite medium scattering isotropically with albedo 1, lit along its normal by a beam
// of unit irradiance (Chandrasekhar 1950's pi F = 1) reflects
//   I(mu) = H(mu) H(1) / (4 pi (1 + mu)),
// H(1) = 2.9078. A slab of optical thickness 4000 is semi-infinite to within the light it lets
// through, 4 / (3 T) = 0.03%.
TEST(SlabDoubling, ADeepIsotropicSlabReflectsAsChandrasekharsHFunction) {
    const std::vector<double> views = {0.1, 0.3, 0.6, 1.0};
    const SlabDoubling slab(0.0, 16, views);
    const SlabDoubling::Field top = slab.diffuse(0.0, 4000.0);
    const ChandrasekharH h;
    const double h1 = h(1.0);
    EXPECT_NEAR(h1, 2.9078, 1e-3);
    for (size_t v = 0; v < views.size(); ++v) {
        const size_t i = slab.cosines().size() - views.size() + v;
        const double expected = h(views[v]) * h1 / (4.0 * kPi * (1.0 + views[v]));
        std::printf("reflected at cosine %.1f: %.5f, Chandrasekhar %.5f\n", views[v], top.up[i], expected);
        EXPECT_NEAR(top.up[i] / expected, 1.0, 2e-3) << views[v];
    }
}

}  // namespace
}  // namespace firmament
