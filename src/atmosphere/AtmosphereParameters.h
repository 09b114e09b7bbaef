#pragma once
// The physical model of the atmosphere (Yusov 2013, after Bruneton and Neyret 2008): a
// spherical Earth under an atmosphere of air molecules (Rayleigh) and aerosols (Mie), each with
// a density that falls exponentially with altitude, and an optional ozone layer that absorbs.
// Every constant lives here; the shaders get them through AtmosphereConstants
// (shaders/atmosphere/atmosphere_structures.hlsli). docs/atmosphere.md gives the equations.
#include "atmosphere/AtmosphereSettings.h"
#include "core/ExrImage.h"
#include "atmosphere/AtmosphereStructures.h"

#include <glm/glm.hpp>

#include <string>

namespace firmament {

// Sizes of the look-up tables.
struct LutDimensions {
    int height = 32;      // 4D scattering LUT: altitude
    int viewZenith = 128;  //   cosine of the view zenith angle
    int sunZenith = 64;    //   cosine of the sun zenith angle
    int sunView = 16;      //   cosine of the angle between view and sun
    int netDensityHeight = 1024;   // 2D net density to the atmosphere top: altitude
    int netDensityZenith = 1024;   //   cosine of the zenith angle
    int ambientLight = 1024;       // 1D ambient sky light: cosine of the sun zenith angle

    static LutDimensions of(LutResolution resolution);
    glm::ivec3 packed3d() const { return {height, viewZenith, sunZenith * sunView}; }  // the 4D table as a 3D texture
};

struct AtmosphereParameters {
    double earthRadius = 6360.0e3;           // m
    double atmosphereHeight = 80.0e3;        // m, top of the atmosphere above the ground
    double rayleighScaleHeight = 7994.0;     // m
    double mieScaleHeight = 1200.0;          // m
    glm::dvec3 rayleighScattering{5.8e-6, 13.5e-6, 33.1e-6};  // 1/m at sea level; Rayleigh extinction is the same
    glm::dvec3 mieScattering{2.0e-5};        // 1/m at sea level
    glm::dvec3 mieExtinction{2.2e-5};        // scattering * (1 + aerosol absorption)
    double mieAsymmetry = 0.76;              // g
    glm::dvec3 ozoneAbsorption{0.0};         // 1/m at the layer's peak; zero without ozone
    double ozoneCentre = 25.0e3;             // m: the tent-shaped layer peaks here ...
    double ozoneHalfWidth = 15.0e3;          // m: ... and falls to zero this far above and below
    int scatteringOrders = 4;                // N: orders 2..N make the high-order table
    int sphereSamples = 128;                 // directions for J (eq. 1) and the ambient light (eq. 3)
    LutDimensions lut;

    static AtmosphereParameters from(const AtmosphereSettings& settings);

    double topRadius() const { return earthRadius + atmosphereHeight; }
    gpu::AtmosphereConstants constants() const;
    // Everything that changes the look-up tables, as text: the cache key's source.
    std::string describe() const;
    // "firmament.atmosphere.*" header attributes: the constants, for captures and table files.
    ExrAttributes exrAttributes() const;
};

// Physical coefficients at the default settings (Intel's sample, Yusov 2013), and the
// scales of the custom colours: colour * scale = coefficient.
inline constexpr double kRayleighColourScale = 4.0e-5;  // (0.145, 0.3375, 0.8276) gives (5.8, 13.5, 33.1)e-6
inline constexpr double kMieColourScale = 2.0e-5;
// Bruneton 2017's ozone: absorption cross-section times the number density at the peak.
inline constexpr glm::dvec3 kOzoneAbsorptionAtPeak{0.650e-6, 1.881e-6, 0.085e-6};

}  // namespace firmament
