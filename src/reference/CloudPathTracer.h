#pragma once
// The clouds' path-traced reference on the CPU (docs/clouds.md, "Path-traced reference"): the
// radiance along a view ray through a CloudMedium, by Monte Carlo paths.
// - Free flights by delta tracking (Woodcock et al. 1965): tentative collisions at the majorant's
//   rate, each real with probability extinction / majorant; the medium scatters all it stops
//   (single-scattering albedo `albedo`, 1 for clouds).
// - At every real collision, the sun by next-event estimation: its irradiance times Henyey and
//   Greenstein's phase function (1941) for the angle between the sun's light and the path, times
//   the transmittance toward the sun by ratio tracking (Novák et al. 2014).
// - Then a new direction from the phase function, as many bounces as the path survives:
//   Russian roulette from bounce 64 on keeps the estimate unbiased, with no cap that would darken
//   a dense cloud.
// - A path that leaves the medium gathers the sky's radiance; one that reaches the ground (a
//   Lambertian plane, optional) gathers the sun and the sky there and bounces on.
// Orders can be selected (first..last scattering event), so that single scattering can be held
// to its closed form and multiple scattering to the scattering table.
#include "reference/CloudMedium.h"

#include <glm/vec3.hpp>

#include <functional>
#include <optional>
#include <random>

namespace firmament {

struct CloudLighting {
    glm::dvec3 toSun{0.0, 1.0, 0.0};          // unit
    glm::dvec3 sunIrradiance{1.0};            // on a plane across the sun's rays, where the clouds are
    std::function<glm::dvec3(glm::dvec3)> sky;  // radiance arriving along -direction, for a unit direction; none: black
    std::optional<double> groundHeight;        // a Lambertian ground at this y, when set
    glm::dvec3 groundAlbedo{0.0};
};

struct CloudPathSettings {
    double asymmetry = 0.9;  // Henyey-Greenstein g
    double albedo = 1.0;     // scattering over extinction
    int firstOrder = 0;      // 0: the unscattered background counts
    int lastOrder = 1 << 30; // the last scattering event counted
    int rouletteFrom = 64;   // bounces before Russian roulette may end a path
};

// Henyey and Greenstein's phase function (1/sr) and a direction drawn from it about `forward`.
double henyeyGreensteinPhase(double cosine, double g);
glm::dvec3 sampleHenyeyGreenstein(glm::dvec3 forward, double g, double u1, double u2);

class CloudPathTracer {
public:
    CloudPathTracer(const CloudMedium& medium, CloudLighting lighting, CloudPathSettings settings)
        : medium_(medium), lighting_(std::move(lighting)), settings_(settings) {}

    // One path's estimate of the radiance arriving at ray.origin along -ray.direction; `events`,
    // when given, receives the number of scattering events (medium and ground) on the path.
    glm::dvec3 radiance(const MediumRay& ray, std::mt19937_64& random, int* events = nullptr) const;
    // The mean of `paths` estimates.
    glm::dvec3 meanRadiance(const MediumRay& ray, int paths, std::mt19937_64& random) const;

    // Delta tracking: the distance to the next real collision before tMax, if any.
    std::optional<double> freeFlight(const MediumRay& ray, double tMax, std::mt19937_64& random) const;
    // Ratio tracking: an unbiased estimate of the transmittance over [0, tMax).
    double transmittance(const MediumRay& ray, double tMax, std::mt19937_64& random) const;

private:
    double groundDistance(const MediumRay& ray) const;
    glm::dvec3 sky(glm::dvec3 direction) const { return lighting_.sky ? lighting_.sky(direction) : glm::dvec3(0.0); }

    const CloudMedium& medium_;
    CloudLighting lighting_;
    CloudPathSettings settings_;
};

}  // namespace firmament
