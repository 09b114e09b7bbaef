#include "reference/HillaireMultipleScatteringTwin.h"

#include <algorithm>
#include <cmath>

namespace firmament::atmosphere {

namespace {

constexpr double kPi = 3.14159265358979323846;
constexpr double kIsotropicPhase = 1.0 / (4.0 * kPi);

// Direction i of `count` spread evenly over the sphere: the spherical Fibonacci set, equal areas,
// the set the device's tables use (src/tables/SphereDirections), written again here in double
// precision so that the twin shares no code with the pass it checks (and stays portable).
glm::dvec3 fibonacciDirection(int i, int count) {
    const double goldenAngle = kPi * (3.0 - std::sqrt(5.0));
    const double y = 1.0 - (2.0 * i + 1.0) / count;
    const double ring = std::sqrt(std::max(0.0, 1.0 - y * y));
    return {ring * std::cos(goldenAngle * i), y, ring * std::sin(goldenAngle * i)};
}

// The scattering coefficient (1/m) at radius r: Rayleigh's and Mie's by their densities.
glm::dvec3 scatteringAt(const ReferenceAtmosphere& reference, double r) {
    const AtmosphereParameters& p = reference.parameters();
    const glm::dvec3 rho = reference.density(r - p.earthRadius);
    return p.rayleighScattering * rho.x + p.mieScattering * rho.y;
}

}  // namespace

MultipleScatteringTransfer hillaireMultipleScattering(const ReferenceAtmosphere& reference, double r, double muS, int directions, int steps) {
    const glm::dvec3 x(0.0, r, 0.0);
    const glm::dvec3 sunDir(std::sqrt(std::max(0.0, 1.0 - muS * muS)), muS, 0.0);
    const double solidAngle = 4.0 * kPi / directions;
    MultipleScatteringTransfer out;
    for (int i = 0; i < directions; ++i) {
        const glm::dvec3 w = fibonacciDirection(i, directions);
        const double length = reference.rayLength(x, w);
        const double dt = length / steps;
        glm::dvec3 secondOrder(0.0), transfer(0.0);
        for (int s = 0; s < steps; ++s) {
            const glm::dvec3 y = x + w * ((s + 0.5) * dt);  // midpoints
            const glm::dvec3 toY = glm::exp(-reference.opticalDepth(reference.netDensity(x, y)));
            const glm::dvec3 scattered = scatteringAt(reference, glm::length(y)) * toY * dt;
            transfer += scattered;
            secondOrder += scattered * reference.sunTransmittance(y, sunDir) * kIsotropicPhase;
        }
        out.secondOrder += secondOrder * kIsotropicPhase * solidAngle;
        out.transfer += transfer * kIsotropicPhase * solidAngle;
    }
    out.psi = out.secondOrder / (glm::dvec3(1.0) - out.transfer);
    return out;
}

glm::dvec3 hillaireMultipleScatteringRadiance(const ReferenceAtmosphere& reference, glm::dvec3 start, glm::dvec3 viewDir, glm::dvec3 sunDir,
                                              int viewSteps, int directions, int steps, double maxLength) {
    const double length = std::min(reference.rayLength(start, viewDir), maxLength);
    const double dt = length / viewSteps;
    glm::dvec3 radiance(0.0);
    for (int s = 0; s < viewSteps; ++s) {
        const glm::dvec3 y = start + viewDir * ((s + 0.5) * dt);
        const double r = glm::length(y);
        const glm::dvec3 toY = glm::exp(-reference.opticalDepth(reference.netDensity(start, y)));
        const double muS = glm::dot(y / r, sunDir);
        radiance += toY * scatteringAt(reference, r) * hillaireMultipleScattering(reference, r, muS, directions, steps).psi * dt;
    }
    return radiance;
}

}  // namespace firmament::atmosphere
