#pragma once
// The atmosphere on the CPU in double precision, computed directly, with no table: the
// reference the GPU's tables are tested against. Integrals use composite 8-point
// Gauss-Legendre quadrature, and the view ray is split where it enters or leaves the Earth's
// shadow, so that no quadrature segment straddles a discontinuity. Positions are relative to
// the Earth's centre, in metres; radiance is per unit sun irradiance.
#include "atmosphere/AtmosphereParameters.h"
#include "atmosphere/yusov/YusovParameterization.h"

#include <glm/glm.hpp>

#include <functional>
#include <random>
#include <vector>

namespace firmament::atmosphere {

class ReferenceAtmosphere {
public:
    explicit ReferenceAtmosphere(const AtmosphereParameters& parameters) : p_(parameters) {}

    // Relative densities at altitude h: Rayleigh, Mie, ozone.
    glm::dvec3 density(double altitude) const;
    // Density integrated along the segment between two points.
    glm::dvec3 netDensity(glm::dvec3 from, glm::dvec3 to) const;
    // Along a ray from altitude h with the given zenith cosine to the top of the atmosphere,
    // as if the ground were not there.
    glm::dvec3 netDensityToTop(double altitude, double cosZenith) const;
    glm::dvec3 opticalDepth(glm::dvec3 netDensity) const;
    // exp(-optical depth) to the top towards the sun; zero where the Earth hides it.
    glm::dvec3 sunTransmittance(glm::dvec3 position, glm::dvec3 sunDir) const;
    // Distance along the ray to the top of the atmosphere, or to the ground when it meets it:
    // when it points below the horizon (cos view < c_h), or, for the ray exactly along the
    // horizon, when `hitsGround` says so (the lower half of the table's view zenith axis).
    double rayLength(glm::dvec3 start, glm::dvec3 dir) const;
    double rayLength(glm::dvec3 start, glm::dvec3 dir, bool hitsGround) const;
    bool hitsGround(glm::dvec3 start, glm::dvec3 dir) const;
    bool inEarthShadow(glm::dvec3 position, glm::dvec3 sunDir) const;

    // Single scattering, Yusov 2013's L_in^(1): the integral along the view ray of
    // T(C -> P) (beta_R rho_R P_R + beta_M rho_M P_M) T_sun(P) ds.
    glm::dvec3 singleScattering(glm::dvec3 start, glm::dvec3 viewDir, glm::dvec3 sunDir) const;
    glm::dvec3 singleScattering(glm::dvec3 start, glm::dvec3 viewDir, glm::dvec3 sunDir, bool hitsGround) const;
    glm::dvec3 singleScattering(const ScatteringCoordinates& c) const;
    glm::dvec3 singleScattering(const ScatteringCoordinates& c, bool aboveHorizon) const;
    // The same per species, without the phase functions (what Yusov's tables store): S_R, the
    // integral of T(C -> P) beta_R rho_R T_sun(P) ds, and S_M.
    struct SpeciesScattering {
        glm::dvec3 rayleigh, mie;
    };
    SpeciesScattering singleScatteringBySpecies(const ScatteringCoordinates& c, bool aboveHorizon) const;
    // The irradiance single scattering gives a horizontal surface at `position`, by quadrature:
    // the upper half of `directions` equal-area directions (a spherical Fibonacci set, as the
    // tables use), each weighted by its cosine, 2 pi / (directions / 2) each.
    glm::dvec3 singleScatteringIrradiance(glm::dvec3 position, glm::dvec3 sunDir, int directions) const;

    // Orders 2..maxOrder of scattering (Yusov 2013's L^H, the ground black as in the tables),
    // by Monte Carlo path tracing: each path walks from the camera, a distance along its ray
    // chosen in proportion to the density of scatterers (sampleByDensity), a new direction
    // uniformly over the sphere, and at every vertex takes the sun's light through one more
    // scattering (next-event estimation). Slow and simple: the estimate and its standard error.
    struct Estimate {
        glm::dvec3 mean, standardError;
    };
    // Where a path's distances are drawn. ByDensity: in proportion to the density of scatterers.
    // TowardSunlight: from an even mixture of that and the density where the sun is seen (the
    // bins of sampleByDensity whose middle is out of the Earth's shadow). In deep twilight the air
    // the sun still lights is high and thin, hundreds of kilometres away, and paths drawn by
    // density alone almost never scatter there: the estimate is nearly always zero and its error
    // bar meaningless. Both are unbiased (the mixture's density is never zero where the
    // scatterers' is not).
    enum class PathSampling { ByDensity, TowardSunlight };
    Estimate highOrderScattering(glm::dvec3 start, glm::dvec3 viewDir, glm::dvec3 sunDir, int maxOrder, int paths, unsigned seed,
                                 PathSampling sampling = PathSampling::ByDensity) const;
    // The same paths' light of orders minOrder..maxOrder only (1: single scattering too).
    Estimate scatteringOrders(glm::dvec3 start, glm::dvec3 viewDir, glm::dvec3 sunDir, int minOrder, int maxOrder, int paths, unsigned seed,
                              PathSampling sampling = PathSampling::ByDensity) const;
    // The sky's irradiance on a horizontal surface at `position`, orders 1..maxOrder (the
    // ground black), by the same paths started in directions drawn by their cosine with the up
    // vector: Yusov 2013's ambient light (eq. 3) and Bruneton's E.
    Estimate skyIrradiance(glm::dvec3 position, glm::dvec3 sunDir, int maxOrder, int paths, unsigned seed) const;

    // A distance along start + s dir, s in [0, length], drawn from two uniform numbers with a
    // probability density proportional to the density of air plus aerosols (piecewise constant
    // over 256 equal bins); `pdf` is its density. Along a long grazing ray the scatterers sit in
    // a few kilometres of it: drawn uniformly, as at first, the estimate is heavy-tailed and
    // its error bar unreliable.
    double sampleByDensity(glm::dvec3 start, glm::dvec3 dir, double length, double u1, double u2, double& pdf) const;
    // The same from PathSampling::TowardSunlight's mixture: both densities are constant over the
    // same bins, and so is their mean, from which the bin is drawn.
    double sampleTowardSunlight(glm::dvec3 start, glm::dvec3 dir, double length, glm::dvec3 sunDir, double u1, double u2, double& pdf) const;

    // A start point and two directions with the given table coordinates (in the x-y plane,
    // the sun towards +z when it is off that plane).
    struct Ray {
        glm::dvec3 start, viewDir, sunDir;
    };
    Ray ray(const ScatteringCoordinates& c) const;

    const AtmosphereParameters& parameters() const { return p_; }

private:
    // Both species' integrals along the view ray in one pass (they share the transmittances):
    // S_R = integral of T(C -> P) beta_R rho_R T_sun(P) ds, and S_M with beta_M rho_M.
    SpeciesScattering speciesScattering(glm::dvec3 start, glm::dvec3 viewDir, glm::dvec3 sunDir, bool hitsGround) const;
    // One path from `start` along `dir`: the light of orders minOrder..maxOrder it gathers.
    glm::dvec3 tracePath(glm::dvec3 start, glm::dvec3 dir, glm::dvec3 sunDir, int minOrder, int maxOrder, PathSampling sampling,
                         std::mt19937_64& random) const;
    // PathSampling::TowardSunlight's next direction from `position`, and its pdf.
    static glm::dvec3 directionTowardSunlight(glm::dvec3 position, glm::dvec3 sunDir, std::mt19937_64& random, double& pdf);
    // A distance drawn from piecewise constant weights over kPathBins equal bins of [0, length].
    static double sampleBins(const std::vector<double>& weights, double length, double u1, double u2, double& pdf);

    AtmosphereParameters p_;
};

// Composite 8-point Gauss-Legendre quadrature of f over [a, b] in `segments` equal parts.
double gaussLegendre(const std::function<double(double)>& f, double a, double b, int segments);
glm::dvec3 gaussLegendre3(const std::function<glm::dvec3(double)>& f, double a, double b, int segments);

// Phase functions, normalised over the sphere.
double rayleighPhase(double cosTheta);            // 3 / (16 pi) (1 + mu^2)
double miePhase(double cosTheta, double g);       // Cornette-Shanks

}  // namespace firmament::atmosphere
