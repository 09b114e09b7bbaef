#pragma once
// The light scattered inside a cloud particle (Yusov 2014, "Pre-computing scattering"):
// homogeneous spheres lit by the sun, their radiance leaving the surface towards every viewer,
// per unit sun irradiance, one layer per optical radius (doubling from the thinnest), so that a
// thin particle scatters as a thin medium and a thick one as a thick one. Single scattering is
// kept without its phase function (which the renderer applies, since its forward peak is sharper
// than the table's directions); so is the light that the delta-M scaled medium's first order
// adds to it (scattered into the forward peak, then once more: the renderer applies the scaled
// phase function); multiple scattering (orders 2 to N of the scaled medium) includes every
// phase. Orders by the paper's recursion:
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
    // The spheres' optical radii (the radius times the extinction, all of it scattering: clouds
    // absorb almost nothing): firstOpticalRadius * 2^k for layer k < opticalRadii. The light is
    // per unit radius: only the optical radius shapes it.
    double firstOpticalRadius = 0.25;
    int opticalRadii = 8;          // 0.25 .. 32
    double asymmetry = 0.9;        // Henyey-Greenstein g: the droplets' strong forward peak
    // Orders 2.. are added until an order adds less than `convergence` of the multiple scattering
    // so far, or up to `orders`.
    int orders = 160;
    double convergence = 1e-3;
    // The surface table: entry point's angle from the sun, view azimuth, view zenith.
    int entryAngles = 32, viewAzimuths = 64, viewZeniths = 16;
    // The field inside: radius, the point's angle from the sun, direction zenith (from the
    // sun's direction) and azimuth (0..pi: the field is mirror-symmetric about the plane through
    // the point and the sun's axis).
    int radii = 12, pointAngles = 32, directionZeniths = 16, directionAzimuths = 8;
    int steps = 48;  // along a ray through the sphere

    double opticalRadius(int layer) const;
    std::string describe() const;  // everything that shapes the table (its key)
    // One layer: the sphere of optical radius `tau`.
    static ParticleScatteringParameters sphere(double tau);
};

// Henyey and Greenstein's phase function (1/sr) for the cosine of the scattering angle.
double henyeyGreenstein(double cosine, double g);

struct ParticleScatteringTable {
    ParticleScatteringParameters parameters;
    // Row by row: x entry angle, y view azimuth, z view zenith within the layer's block of
    // viewZeniths slices (the GPU's 3D texture's order).
    std::vector<float> single;    // phase excluded
    std::vector<float> peak;      // the scaled medium's first order beyond single's share of it, phase excluded
    std::vector<float> multiple;  // orders 2..N
    std::vector<int> orders;      // the last order added, by layer

    size_t index(int entry, int azimuth, int zenith, int layer = 0) const {
        return ((static_cast<size_t>(layer) * parameters.viewZeniths + zenith) * parameters.viewAzimuths + azimuth) * parameters.entryAngles + entry;
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

// Single scattering of one surface ray through the sphere of optical radius tau by quadrature
// (phase excluded), with `steps` midpoints.
double singleScatteringQuadrature(double tau, const SurfaceRay& ray, int steps);

// The table's file: R single, G multiple, B peak, tiles of entry angle x view azimuth side by side, one per
// view zenith, the layers' rows of tiles one above the other; its header holds the key (the parameters' description and the format) and says
// what it is. Reading throws Error naming the file and the problem (missing, not made for
// `expected`: run tools/generate-cloud-scattering).
std::string particleScatteringKey(const ParticleScatteringParameters& p);
void writeParticleScattering(const std::filesystem::path& path, const ParticleScatteringTable& table);
ParticleScatteringTable readParticleScattering(const std::filesystem::path& path, const ParticleScatteringParameters& expected);

// The whole table; `progress` (0..1) is called after each order. `onlyLayer` >= 0 computes that
// layer alone (the others stay zero).
ParticleScatteringTable computeParticleScattering(const ParticleScatteringParameters& p, const std::function<void(double)>& progress = {},
                                                  int onlyLayer = -1);

}  // namespace firmament
