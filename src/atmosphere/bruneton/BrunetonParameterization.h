#pragma once
// Bruneton and Neyret 2008's parameterization of their tables (Bruneton and Neyret 2008; the paper's
// section 4) and its inverse on the CPU, in double precision: the twin of
// shaders/atmosphere/bruneton/parameterization.hlsli, for the tests and the reference.
//
// The 4D in-scatter table S(r, mu, mu_s, nu) is indexed by radius r (from the Earth's centre),
// the cosines of the view zenith (mu) and sun zenith (mu_s) angles and of the sun-view angle (nu):
//  - u_r  = rho / H, with rho = sqrt(r^2 - Rg^2) and H = sqrt(Rt^2 - Rg^2): the distance to the
//    horizon, which crowds radii near the ground;
//  - u_mu: the view zenith axis has two halves. Rays that meet the ground use the lower half,
//    with the distance to the ground over rho (the horizon at its first texel); the others the
//    upper half, with the distance to the top of the atmosphere over rho + H (the zenith first,
//    the horizon last). The horizon is the seam between the halves, so no texel straddles it;
//  - u_mu_s = max((1 - exp(-3 mu_s - 0.6)) / (1 - exp(-3.6)), 0): suns below mu_s = -0.2
//    light nothing the table needs;
//  - u_nu = (1 + nu) / 2, interpolated by hand between slices of the 3D texture.
// Every unit coordinate u in [0, 1] of an axis of n texels lands on texel centres:
// x = 0.5 / n + u (1 - 1 / n).
#include "atmosphere/AtmosphereParameters.h"

#include <glm/glm.hpp>

namespace firmament::atmosphere::bruneton {

// Sizes of the tables. Full is the paper's (and Bruneton and Neyret 2008's) size.
struct Dimensions {
    int transmittanceMu = 256, transmittanceR = 64;  // 2D transmittance to the top of the atmosphere
    int irradianceMuS = 64, irradianceR = 16;        // 2D ground irradiance
    int r = 32, mu = 128, muS = 32, nu = 8;          // 4D in-scatter

    static Dimensions of(LutResolution resolution);
    glm::ivec3 packed3d() const { return {muS * nu, mu, r}; }  // x: nu slice * N_mu_s + mu_s
};

// A point of the in-scatter table's domain.
struct Coordinates {
    double r = 0.0;    // m, from the Earth's centre
    double mu = 1.0;   // cosine of the view zenith angle
    double muS = 1.0;  // cosine of the sun zenith angle
    double nu = 1.0;   // cosine of the sun-view angle
};

double unitToTexture(double u, int n);  // 0.5 / n + u (1 - 1 / n)
double textureToUnit(double x, int n);

// Transmittance table: u_r = sqrt((r - Rg) / (Rt - Rg)), u_mu = atan((mu + 0.15) / 1.15 tan 1.5) / 1.5
// (Bruneton and Neyret 2008), so that texels crowd near the ground and near the horizon.
glm::dvec2 transmittanceUnit(const AtmosphereParameters& p, double r, double mu);  // (u_mu, u_r)
Coordinates transmittanceCoordinates(const AtmosphereParameters& p, glm::dvec2 unit);  // r and mu

// Irradiance table: linear, u_r = (r - Rg) / (Rt - Rg) and u_mu_s = (mu_s + 0.2) / 1.2.
glm::dvec2 irradianceUnit(const AtmosphereParameters& p, double r, double muS);  // (u_mu_s, u_r)
Coordinates irradianceCoordinates(const AtmosphereParameters& p, glm::dvec2 unit);  // r and mu_s

// The ray meets the ground: mu below the horizon's cosine -sqrt(1 - (Rg / r)^2).
bool hitsGround(const AtmosphereParameters& p, double r, double mu);

// In-scatter table, unit coordinates (u_r, u_mu, u_mu_s, u_nu) with u_mu already placed in
// its half: [0, 0.5) for rays that meet the ground (`groundHalf`), [0.5, 1] for the others,
// as texture coordinates of the N_mu texels.
glm::dvec4 inscatterUnit(const AtmosphereParameters& p, const Dimensions& n, const Coordinates& c, bool groundHalf);
// The world point of a texel of the packed 3D table (x: nu slice * N_mu_s + mu_s, y: mu, z: r),
// as the pre-computation computes it (nu clamped to what mu and mu_s allow).
Coordinates inscatterTexel(const AtmosphereParameters& p, const Dimensions& n, glm::ivec3 texel);
// The radii of the first and last layers: kept just off the ground and the top, where rho or
// the distance to the top vanish.
inline constexpr double kLowestLayer = 10.0;  // m above the ground
inline constexpr double kHighestLayer = 1.0;  // m below the top

}  // namespace firmament::atmosphere::bruneton
