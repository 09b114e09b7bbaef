#pragma once
// The light scattered inside a cloud particle (Yusov 2014, "Pre-computing scattering"): a
// homogeneous reference sphere lit by the sun, its radiance leaving the surface towards every
// viewer, per unit sun irradiance. Single scattering is kept without its phase function (which
// the renderer applies, since its forward peak is sharper than the table's directions);
// multiple scattering (orders 2 to N) includes every phase. Orders by the paper's recursion:
//   J_n(P, w) = integral over the sphere of L_{n-1}(P, w') p(w . w') dw'
//   L_n(P, w) = integral along -w to the surface of beta e^(-beta t) J_n(P - t w, w) dt
// on a 4D field inside the sphere (axially symmetric about the sun's direction), then the
// radiance leaving each surface point in each direction. The orders run in the delta-M scaled
// medium (Wiscombe 1977), whose forward peak the field's directions can hold. Computed on the CPU
// by `firmament --generate-cloud-scattering` and shipped as media/clouds/particle-scattering.exr
// (docs/clouds.md, "Scattering table").
#include <glm/vec3.hpp>

#include <filesystem>
#include <functional>
#include <string>
#include <vector>

namespace firmament {

struct ParticleScatteringParameters {
    double radius = 200.0;      // the reference particle (m)
    double extinction = 0.07;   // 1/m: all of it scattering (clouds absorb almost nothing)
    double asymmetry = 0.9;     // Henyey-Greenstein g: the droplets' strong forward peak
    int orders = 16;            // the last scattering order counted (within 1% of 40 orders)
    // The surface table: entry point's angle from the sun, view azimuth, view zenith.
    int entryAngles = 32, viewAzimuths = 64, viewZeniths = 16;
    // The field inside: radius, the point's angle from the sun, direction zenith (from the
    // sun's direction) and azimuth (0..pi: the field is mirror-symmetric about the plane through
    // the point and the sun's axis).
    int radii = 12, pointAngles = 32, directionZeniths = 16, directionAzimuths = 8;
    int steps = 48;  // along a ray through the sphere

    double opticalRadius() const { return radius * extinction; }
    std::string describe() const;  // everything that shapes the table (its key)
};

// Henyey and Greenstein's phase function (1/sr) for the cosine of the scattering angle.
double henyeyGreenstein(double cosine, double g);

struct ParticleScatteringTable {
    ParticleScatteringParameters parameters;
    // Row by row: x entry angle, y view azimuth, z view zenith (the GPU's 3D texture's order).
    std::vector<float> single;    // phase excluded
    std::vector<float> multiple;  // orders 2..N

    size_t index(int entry, int azimuth, int zenith) const {
        return (static_cast<size_t>(zenith) * parameters.viewAzimuths + azimuth) * parameters.entryAngles + entry;
    }
};

// The surface ray of texel (entry, azimuth, zenith): its entry point on the unit sphere and its
// direction into the sphere, the sun along +z. The coordinates: u0 = the entry point's angle from
// the sun / pi; u1 = the view's azimuth / 2pi + 1/2 in the frame Z = -s, X = the sun's direction
// across Z, Y = Z x X; u2 = the view's angle from -s / (pi / 2). Texel centres.
struct SurfaceRay {
    glm::dvec3 entry;
    glm::dvec3 direction;
};
SurfaceRay scatteringTexelRay(const ParticleScatteringParameters& p, int entry, int azimuth, int zenith);
SurfaceRay scatteringRay(double u0, double u1, double u2);

// Single scattering of one surface ray by quadrature (phase excluded), with `steps` midpoints.
double singleScatteringQuadrature(const ParticleScatteringParameters& p, const SurfaceRay& ray, int steps);

// The table's file: R single, G multiple, tiles of entry angle x view azimuth side by side, one per
// view zenith; its header holds the key (the parameters' description and the format) and says
// what it is. Reading throws Error naming the file and the problem (missing, not made for
// `expected`: run tools/generate-cloud-scattering).
std::string particleScatteringKey(const ParticleScatteringParameters& p);
void writeParticleScattering(const std::filesystem::path& path, const ParticleScatteringTable& table);
ParticleScatteringTable readParticleScattering(const std::filesystem::path& path, const ParticleScatteringParameters& expected);

// The whole table; `progress` (0..1) is called after each order.
ParticleScatteringTable computeParticleScattering(const ParticleScatteringParameters& p, const std::function<void(double)>& progress = {});

}  // namespace firmament
