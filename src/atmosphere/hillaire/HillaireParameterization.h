#pragma once
// Hillaire 2020's parameterization of its four tables ("A Scalable and Production Ready Sky and
// Atmosphere Rendering Technique", section 5) and their inverses on the CPU, in double
// precision: the twin of the shaders to come, for the tests and the reference.
//
//  - Transmittance to the top of the atmosphere, T(r, mu): Bruneton 2017's mapping, which the
//    paper adopts. With H = sqrt(Rt^2 - Rg^2) and rho = sqrt(r^2 - Rg^2) (the distance to the
//    horizon), x_r = rho / H crowds texels near the ground; x_mu = (d - d_min) / (d_max - d_min),
//    d the distance to the top along mu, between d_min = Rt - r (straight up) and
//    d_max = rho + H (along the horizon, the longest ray that does not meet the ground), so that
//    the zenith is x_mu = 0 and the horizon x_mu = 1. Rays below the horizon are not stored: the
//    ground stops them.
//  - Multiple scattering Psi_ms(r, mu_s): linear, u = 0.5 + 0.5 mu_s, v = (r - Rg) / (Rt - Rg).
//  - Sky view L(v, phi) for the camera's altitude: the longitude phi is the view's azimuth from
//    the sun's, u = sqrt(0.5 - 0.5 cos phi), which crowds texels toward the sun; the latitude is
//    the paper's square-root crowding about the horizon, measured from the altitude's true
//    horizon (its zenith angle pi - beta, cos beta = rho / r), so that the horizon lies on
//    v = 0.5 from any altitude: v = 0.5 (1 - sqrt(1 - theta / (pi - beta))) above it and
//    v = 0.5 (1 + sqrt((theta - (pi - beta)) / beta)) below, theta the view's zenith angle.
//  - Aerial perspective: froxels of the camera's frustum, slices linear in distance up to
//    kAerialPerspectiveDepth.
// Every unit coordinate u in [0, 1] of an axis of n texels lands on texel centres:
// x = 0.5 / n + u (1 - 1 / n), as in Bruneton's and Yusov's tables.
#include "atmosphere/AtmosphereParameters.h"

#include <glm/glm.hpp>

namespace firmament::atmosphere::hillaire {

// Sizes of the tables. Full is the paper's: transmittance 256 x 64, multiple scattering
// 32 x 32, sky view 192 x 108, aerial perspective 32 x 32 x 32; and the sky irradiance that
// Firmament adds, 64 x 16 (Bruneton's irradiance table's size).
struct Dimensions {
    int transmittanceMu = 256, transmittanceR = 64;
    int multipleScatteringMuS = 32, multipleScatteringR = 32;
    int skyViewLongitude = 192, skyViewLatitude = 108;
    int aerialPerspective = 32;  // froxels along each axis
    int irradianceMuS = 64, irradianceR = 16;  // Firmament's sky irradiance for the ground (the multiple scattering's mapping)

    static Dimensions of(LutResolution resolution);
};

// The aerial perspective volume's depth (m): 32 km, the paper's.
inline constexpr double kAerialPerspectiveDepth = 32.0e3;

double unitToTexture(double u, int n);  // 0.5 / n + u (1 - 1 / n)
double textureToUnit(double x, int n);

// Distance from radius r along the zenith cosine mu to the top of the atmosphere.
double distanceToTop(const AtmosphereParameters& p, double r, double mu);

// Transmittance table: (x_mu, x_r) for a ray from radius r (Rg to Rt) along mu (not below the
// horizon), and back.
glm::dvec2 transmittanceUnit(const AtmosphereParameters& p, double r, double mu);
struct RadiusAndCosine {
    double r = 0.0;   // m, from the Earth's centre
    double mu = 1.0;  // a zenith cosine: of the view (transmittance, sky view) or of the sun (multiple scattering)
};
RadiusAndCosine transmittanceCoordinates(const AtmosphereParameters& p, glm::dvec2 unit);

// Multiple scattering table: (u, v) for the sun's zenith cosine mu_s at radius r, and back.
glm::dvec2 multipleScatteringUnit(const AtmosphereParameters& p, double r, double muS);
RadiusAndCosine multipleScatteringCoordinates(const AtmosphereParameters& p, glm::dvec2 unit);

// Sky-view table at radius r: (u, v) for a view of zenith cosine mu whose azimuth is `cosAzimuth`
// from the sun's (cosine of the angle between their horizontal parts), and back: the view's zenith
// cosine and that azimuth's cosine.
glm::dvec2 skyViewUnit(const AtmosphereParameters& p, double r, double mu, double cosAzimuth);
struct SkyViewDirection {
    double mu = 1.0;
    double cosAzimuth = 1.0;
};
SkyViewDirection skyViewDirection(const AtmosphereParameters& p, double r, glm::dvec2 unit);
// The zenith angle of the true horizon seen from radius r (pi / 2 on the ground, more above it).
double horizonZenithAngle(const AtmosphereParameters& p, double r);

// Aerial perspective: the unit depth coordinate of a point `distance` metres from the camera
// (beyond kAerialPerspectiveDepth: 1), and back.
double aerialPerspectiveUnit(double distance);
double aerialPerspectiveDistance(double unit);

}  // namespace firmament::atmosphere::hillaire
