#pragma once
// Yusov's parameterization of the 4D scattering tables (Yusov 2013, eq. 4-7) and its
// inverse on the CPU, in double precision: the twin of
// shaders/atmosphere/yusov/parameterization.hlsli, for the tests and the reference.
#include "atmosphere/AtmosphereParameters.h"

#include <glm/glm.hpp>

namespace firmament::atmosphere {

// A point of the table's domain: altitude and the cosines of the view zenith, sun zenith and
// sun-view angles.
struct ScatteringCoordinates {
    double altitude = 0.0;
    double cosView = 1.0;
    double cosSun = 1.0;
    double cosSunView = 1.0;
};

// Unit coordinates, each in [0, 1]; `aboveHorizon` says which half the view zenith is in.
struct UnitCoordinates {
    double altitude = 0.0;
    double viewZenith = 0.0;
    bool aboveHorizon = true;
    double sunZenith = 0.0;
    double sunView = 0.0;
};

double cosHorizon(const AtmosphereParameters& p, double altitude);  // c_h = -sqrt(h (2R + h)) / (R + h)

UnitCoordinates toUnit(const AtmosphereParameters& p, const ScatteringCoordinates& c);
// Which half is used comes from `c.aboveHorizon`, not from the angle (horizon consistency).
UnitCoordinates toUnit(const AtmosphereParameters& p, const ScatteringCoordinates& c, bool aboveHorizon);
ScatteringCoordinates fromUnit(const AtmosphereParameters& p, const UnitCoordinates& u);

// Bounds of the sun-view cosine given the two zenith cosines: [cos(a + p), cos(a - p)].
double clampSunView(double cosView, double cosSun, double cosSunView);

// The world point of a texel of the packed 3D table (x: altitude, y: view zenith, z: sun-view
// slice * N_sunZenith + sun zenith), as the pre-computation shader computes it.
ScatteringCoordinates texelToWorld(const AtmosphereParameters& p, glm::ivec3 texel);

}  // namespace firmament::atmosphere
