#pragma once
// Hillaire 2020's approximation of multiple scattering (section 5.5), on the CPU in double
// precision, over the reference atmosphere (ReferenceAtmosphere): the twin that the model's
// multiple-scattering table will be held to, and the means of holding the approximation itself
// to the reference's path-traced orders of scattering.
//
// At a point x with the sun at zenith cosine mu_s, with an isotropic phase p_u = 1 / (4 pi) from
// the second order on and the ground black (as the other models' tables have it):
//   L_2  = sum over directions w of p_u dw  integral along w of sigma_s(y) T(x, y) T_sun(y) p_u dt
//          (the first-order light reaching x, averaged over the sphere),
//   f_ms = sum over directions w of p_u dw  integral along w of sigma_s(y) T(x, y) dt
//          (the share of an isotropic field that one more scattering sends back to x),
//   Psi_ms = L_2 (1 + f_ms + f_ms^2 + ...) = L_2 / (1 - f_ms).
// The orders from the second on seen along a view are then the integral of
// T(x, y) sigma_s(y) Psi_ms(y) along it. Radiance is per unit sun irradiance.
#include "reference/ReferenceAtmosphere.h"

#include <glm/glm.hpp>

namespace firmament::atmosphere {

struct MultipleScatteringTransfer {
    glm::dvec3 secondOrder{0.0};  // L_2
    glm::dvec3 transfer{0.0};     // f_ms
    glm::dvec3 psi{0.0};          // Psi_ms = L_2 / (1 - f_ms)
};

// At radius r (from the Earth's centre) with the sun at zenith cosine muS: `directions` over the
// sphere (a spherical Fibonacci set), each ray marched in `steps` equal steps (the paper's 64
// and 20).
MultipleScatteringTransfer hillaireMultipleScattering(const ReferenceAtmosphere& reference, double r, double muS, int directions = 64,
                                                     int steps = 20);

// The orders from the second on, seen from `start` along `viewDir` with the sun along `sunDir`, by
// the approximation: `viewSteps` equal steps along the view (to its end, or `maxLength` metres
// when nearer), Psi_ms computed at each.
glm::dvec3 hillaireMultipleScatteringRadiance(const ReferenceAtmosphere& reference, glm::dvec3 start, glm::dvec3 viewDir, glm::dvec3 sunDir,
                                              int viewSteps = 16, int directions = 64, int steps = 20, double maxLength = 1e300);

}  // namespace firmament::atmosphere
