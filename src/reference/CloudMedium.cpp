#include "reference/CloudMedium.h"

#include "clouds/ParticleDensity.h"

#include <glm/common.hpp>
#include <glm/geometric.hpp>
#include <glm/vector_relational.hpp>

#include <algorithm>
#include <cmath>
#include <limits>

namespace firmament {

namespace {
constexpr double kInfinity = std::numeric_limits<double>::infinity();

// The ray's stretch inside the slab bottom <= y <= top, clipped to [0, tMax]; false when empty.
bool slabInterval(const MediumRay& ray, double bottom, double top, double tMax, double& t0, double& t1) {
    t0 = 0.0;
    t1 = tMax;
    if (std::abs(ray.direction.y) < 1e-300) return ray.origin.y >= bottom && ray.origin.y <= top;
    double a = (bottom - ray.origin.y) / ray.direction.y, b = (top - ray.origin.y) / ray.direction.y;
    if (a > b) std::swap(a, b);
    t0 = std::max(t0, a);
    t1 = std::min(t1, b);
    return t1 > t0;
}

// The ray's stretch inside the box [lower, upper], clipped to [0, tMax] (the slab method).
bool boxInterval(const MediumRay& ray, glm::dvec3 lower, glm::dvec3 upper, double tMax, double& t0, double& t1) {
    t0 = 0.0;
    t1 = tMax;
    for (int axis = 0; axis < 3; ++axis) {
        if (std::abs(ray.direction[axis]) < 1e-300) {
            if (ray.origin[axis] < lower[axis] || ray.origin[axis] > upper[axis]) return false;
            continue;
        }
        double a = (lower[axis] - ray.origin[axis]) / ray.direction[axis], b = (upper[axis] - ray.origin[axis]) / ray.direction[axis];
        if (a > b) std::swap(a, b);
        t0 = std::max(t0, a);
        t1 = std::min(t1, b);
    }
    return t1 > t0;
}
}  // namespace

double HomogeneousSlab::extinction(const glm::dvec3& p) const { return p.y >= bottom_ && p.y <= top_ ? extinction_ : 0.0; }

void HomogeneousSlab::majorants(const MediumRay& ray, double tMax, const MajorantVisitor& visit) const {
    double t0, t1;
    if (slabInterval(ray, bottom_, top_, tMax, t0, t1)) visit(t0, t1, extinction_);
}

double HomogeneousSphere::extinction(const glm::dvec3& p) const {
    const glm::dvec3 offset = p - centre_;
    return glm::dot(offset, offset) <= radius_ * radius_ ? extinction_ : 0.0;
}

void HomogeneousSphere::majorants(const MediumRay& ray, double tMax, const MajorantVisitor& visit) const {
    const glm::dvec3 offset = ray.origin - centre_;
    const double b = glm::dot(offset, ray.direction), c = glm::dot(offset, offset) - radius_ * radius_;
    const double discriminant = b * b - c;
    if (discriminant <= 0.0) return;
    const double root = std::sqrt(discriminant);
    const double t0 = std::max(0.0, -b - root), t1 = std::min(tMax, -b + root);
    if (t1 > t0) visit(t0, t1, extinction_);
}

ParticleMedium::ParticleMedium(std::vector<ModelParticle> particles, double earthRadius, ParticleDensityMethod method, double extinctionAtDensity1)
    : method_(method), extinction1_(extinctionAtDensity1) {
    glm::dvec3 lower(kInfinity), upper(-kInfinity);
    for (const ModelParticle& q : particles) {
        if (q.density <= 0.0f || q.horizontalRadius <= 0.0f || q.verticalRadius <= 0.0f) continue;
        Placed placed;
        placed.centre = glm::dvec3(q.centre);
        // The frame of shaders/clouds/particle_shape.hlsli's particleFrame().
        placed.normal = glm::normalize(placed.centre + glm::dvec3(0.0, earthRadius, 0.0));
        placed.tangent = glm::normalize(glm::cross(placed.normal, glm::dvec3(0.0, 0.0, 1.0)));
        placed.bitangent = glm::cross(placed.tangent, placed.normal);
        placed.radii = glm::dvec3(q.horizontalRadius, q.verticalRadius, q.horizontalRadius);
        placed.density = q.density;
        placed.cosAzimuth = std::cos(static_cast<double>(q.azimuth));
        placed.sinAzimuth = std::sin(static_cast<double>(q.azimuth));
        placed.boundingRadius = std::max(placed.radii.x, placed.radii.y);
        lower = glm::min(lower, placed.centre - placed.boundingRadius);
        upper = glm::max(upper, placed.centre + placed.boundingRadius);
        particles_.push_back(placed);
    }
    if (particles_.empty()) return;
    // Cells of one size, about eight per particle, at most 256 along an axis.
    const glm::dvec3 extent = glm::max(upper - lower, glm::dvec3(1e-3));
    const double side = std::cbrt(extent.x * extent.y * extent.z / (8.0 * static_cast<double>(particles_.size())));
    for (int axis = 0; axis < 3; ++axis) cells_[axis] = std::clamp(static_cast<int>(std::ceil(extent[axis] / side)), 1, 256);
    lower_ = lower;
    cellSize_ = extent / glm::dvec3(cells_);
    lists_.assign(static_cast<size_t>(cells_.x) * cells_.y * cells_.z, {});
    cellMajorant_.assign(lists_.size(), 0.0);
    for (unsigned k = 0; k < particles_.size(); ++k) {
        const Placed& q = particles_[k];
        const glm::ivec3 first = glm::clamp(glm::ivec3(glm::floor((q.centre - q.boundingRadius - lower_) / cellSize_)), glm::ivec3(0), cells_ - 1);
        const glm::ivec3 last = glm::clamp(glm::ivec3(glm::floor((q.centre + q.boundingRadius - lower_) / cellSize_)), glm::ivec3(0), cells_ - 1);
        for (int z = first.z; z <= last.z; ++z)
            for (int y = first.y; y <= last.y; ++y)
                for (int x = first.x; x <= last.x; ++x) {
                    const size_t cell = cellIndex({x, y, z});
                    lists_[cell].push_back(k);
                    // particleDensity() is at most 1 for every method.
                    cellMajorant_[cell] += q.density * extinction1_;
                }
    }
}

size_t ParticleMedium::mostParticlesInACell() const {
    size_t most = 0;
    for (const auto& list : lists_) most = std::max(most, list.size());
    return most;
}

double ParticleMedium::particleExtinction(const Placed& q, const glm::dvec3& p) const {
    const glm::dvec3 offset = p - q.centre;
    const glm::dvec3 unit = glm::dvec3(glm::dot(offset, q.tangent), glm::dot(offset, q.normal), glm::dot(offset, q.bitangent)) / q.radii;
    if (glm::dot(unit, unit) >= 1.0) return 0.0;
    // Turned by the azimuth about y, as the GPU adds it to the optical depth table's entry azimuth.
    const glm::dvec3 turned(unit.x * q.cosAzimuth - unit.z * q.sinAzimuth, unit.y, unit.x * q.sinAzimuth + unit.z * q.cosAzimuth);
    return q.density * extinction1_ * particleDensity(glm::vec3(turned), method_);
}

double ParticleMedium::extinction(const glm::dvec3& p) const {
    if (particles_.empty()) return 0.0;
    const glm::ivec3 c(glm::floor((p - lower_) / cellSize_));
    if (glm::any(glm::lessThan(c, glm::ivec3(0))) || glm::any(glm::greaterThanEqual(c, cells_))) return 0.0;
    double sum = 0.0;
    for (unsigned k : lists_[cellIndex(c)]) sum += particleExtinction(particles_[k], p);
    return sum;
}

void ParticleMedium::majorants(const MediumRay& ray, double tMax, const MajorantVisitor& visit) const {
    if (particles_.empty()) return;
    double t0, t1;
    const glm::dvec3 upper = lower_ + cellSize_ * glm::dvec3(cells_);
    if (!boxInterval(ray, lower_, upper, tMax, t0, t1)) return;
    const glm::dvec3 start = ray.origin + ray.direction * t0;
    glm::ivec3 c = glm::clamp(glm::ivec3(glm::floor((start - lower_) / cellSize_)), glm::ivec3(0), cells_ - 1);
    glm::ivec3 step(0);
    glm::dvec3 next(kInfinity), delta(kInfinity);
    for (int axis = 0; axis < 3; ++axis) {
        const double d = ray.direction[axis];
        if (d > 0.0) {
            step[axis] = 1;
            next[axis] = (lower_[axis] + (c[axis] + 1) * cellSize_[axis] - ray.origin[axis]) / d;
            delta[axis] = cellSize_[axis] / d;
        } else if (d < 0.0) {
            step[axis] = -1;
            next[axis] = (lower_[axis] + c[axis] * cellSize_[axis] - ray.origin[axis]) / d;
            delta[axis] = -cellSize_[axis] / d;
        }
    }
    double t = t0;
    while (t < t1) {
        const int axis = next.x < next.y ? (next.x < next.z ? 0 : 2) : (next.y < next.z ? 1 : 2);
        const double leave = std::min(next[axis], t1);
        const double majorant = cellMajorant_[cellIndex(c)];
        if (majorant > 0.0 && leave > t && !visit(t, leave, majorant)) return;
        t = leave;
        c[axis] += step[axis];
        if (c[axis] < 0 || c[axis] >= cells_[axis]) return;
        next[axis] += delta[axis];
    }
}

}  // namespace firmament
