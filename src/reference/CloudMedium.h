#pragma once
// The clouds' participating medium as the path-traced reference sees it (docs/clouds.md,
// "Path-traced reference"): an extinction coefficient at every point, and upper bounds of it
// (majorants) along a ray, which delta and ratio tracking need. Three media: a homogeneous slab
// and a homogeneous sphere, whose light has closed forms or the scattering table's generator to
// be checked against, and the particle field itself: every particle's own density function
// (shaders/clouds/particle_density.hlsli, turned by its azimuth), times its density and the
// extinction at density 1, summed where particles overlap, found through a uniform grid.
#include "clouds/CloudSettings.h"
#include "reference/CloudFieldTwin.h"

#include <glm/vec3.hpp>

#include <functional>
#include <vector>

namespace firmament {

struct MediumRay {
    glm::dvec3 origin;
    glm::dvec3 direction;  // unit
};

// visit(t0, t1, majorant) over consecutive stretches of a ray; returning false stops the walk.
using MajorantVisitor = std::function<bool(double t0, double t1, double majorant)>;

class CloudMedium {
public:
    virtual ~CloudMedium() = default;
    // The extinction coefficient at p (1/m); all of it scattering (clouds absorb almost nothing).
    virtual double extinction(const glm::dvec3& p) const = 0;
    // Stretches of [0, tMax) along the ray, in order, each with a bound of the extinction on it.
    // Stretches with no medium may be left out.
    virtual void majorants(const MediumRay& ray, double tMax, const MajorantVisitor& visit) const = 0;
};

// Extinction `extinction` between the heights `bottom` and `top` (y), unbounded across.
class HomogeneousSlab final : public CloudMedium {
public:
    HomogeneousSlab(double bottom, double top, double extinction) : bottom_(bottom), top_(top), extinction_(extinction) {}
    double extinction(const glm::dvec3& p) const override;
    void majorants(const MediumRay& ray, double tMax, const MajorantVisitor& visit) const override;

private:
    double bottom_, top_, extinction_;
};

// Extinction `extinction` inside a sphere.
class HomogeneousSphere final : public CloudMedium {
public:
    HomogeneousSphere(glm::dvec3 centre, double radius, double extinction) : centre_(centre), radius_(radius), extinction_(extinction) {}
    double extinction(const glm::dvec3& p) const override;
    void majorants(const MediumRay& ray, double tMax, const MajorantVisitor& visit) const override;

private:
    glm::dvec3 centre_;
    double radius_, extinction_;
};

// The medium the particles describe. Each particle is an ellipsoid on a planet of `earthRadius`
// (centre at (0, -earthRadius, 0)): y along the planet's normal through its centre, x and z two
// tangents, radii (horizontal, vertical, horizontal); its density at a point is
// density * particleDensity(the point in its unit-sphere space turned by its azimuth, method),
// and the medium's extinction is the sum over particles times `extinctionAtDensity1`.
class ParticleMedium final : public CloudMedium {
public:
    ParticleMedium(std::vector<ModelParticle> particles, double earthRadius, ParticleDensityMethod method, double extinctionAtDensity1);
    double extinction(const glm::dvec3& p) const override;
    // The grid's cells the ray crosses (3D DDA, Amanatides and Woo 1987), each with the sum of the
    // densities of the particles that may reach into it times the extinction at density 1.
    void majorants(const MediumRay& ray, double tMax, const MajorantVisitor& visit) const override;

    // The grid's cells along a side, and the largest number of particles one cell lists.
    glm::ivec3 cells() const { return cells_; }
    size_t mostParticlesInACell() const;

private:
    struct Placed {
        glm::dvec3 centre, tangent, normal, bitangent, radii;
        double density, cosAzimuth, sinAzimuth, boundingRadius;
    };
    double particleExtinction(const Placed& q, const glm::dvec3& p) const;
    size_t cellIndex(glm::ivec3 c) const { return (static_cast<size_t>(c.z) * cells_.y + c.y) * cells_.x + c.x; }

    std::vector<Placed> particles_;
    ParticleDensityMethod method_;
    double extinction1_;
    glm::dvec3 lower_{0.0}, cellSize_{1.0};
    glm::ivec3 cells_{0};
    std::vector<std::vector<unsigned>> lists_;  // per cell, the particles whose bounding sphere's box overlaps it
    std::vector<double> cellMajorant_;
};

}  // namespace firmament
