#include "reference/CloudPathTracer.h"

#include <glm/geometric.hpp>

#include <algorithm>
#include <cmath>
#include <limits>

namespace firmament {

namespace {
constexpr double kPi = 3.14159265358979323846;
constexpr double kInfinity = std::numeric_limits<double>::infinity();
// A path is never cut for its length, but a bug must not hang the program: far beyond any cloud's
// (a 3 km layer of extinction 0.07 takes thousands of events).
constexpr int kBounceLimit = 10000000;

double uniform(std::mt19937_64& random) { return std::uniform_real_distribution<double>(0.0, 1.0)(random); }

// Two unit vectors across `w`.
void basis(glm::dvec3 w, glm::dvec3& u, glm::dvec3& v) {
    const glm::dvec3 helper = std::abs(w.x) < 0.9 ? glm::dvec3(1.0, 0.0, 0.0) : glm::dvec3(0.0, 1.0, 0.0);
    u = glm::normalize(glm::cross(helper, w));
    v = glm::cross(w, u);
}

glm::dvec3 around(glm::dvec3 axis, double cosine, double phi) {
    glm::dvec3 u, v;
    basis(axis, u, v);
    const double sine = std::sqrt(std::max(0.0, 1.0 - cosine * cosine));
    return glm::normalize(cosine * axis + sine * (std::cos(phi) * u + std::sin(phi) * v));
}
}  // namespace

// p(cos) = (1 - g^2) / (4 pi (1 + g^2 - 2 g cos)^(3/2))
double henyeyGreensteinPhase(double cosine, double g) {
    const double denominator = 1.0 + g * g - 2.0 * g * cosine;
    return (1.0 - g * g) / (4.0 * kPi * denominator * std::sqrt(denominator));
}

// The inverse of the phase function's cumulative distribution in the cosine.
glm::dvec3 sampleHenyeyGreenstein(glm::dvec3 forward, double g, double u1, double u2) {
    double cosine;
    if (std::abs(g) < 1e-6) {
        cosine = 1.0 - 2.0 * u1;
    } else {
        const double s = (1.0 - g * g) / (1.0 - g + 2.0 * g * u1);
        cosine = std::clamp((1.0 + g * g - s * s) / (2.0 * g), -1.0, 1.0);
    }
    return around(forward, cosine, 2.0 * kPi * u2);
}

std::optional<double> CloudPathTracer::freeFlight(const MediumRay& ray, double tMax, std::mt19937_64& random) const {
    std::optional<double> collision;
    medium_.majorants(ray, tMax, [&](double t0, double t1, double majorant) {
        double t = t0;
        for (;;) {
            t -= std::log(1.0 - uniform(random)) / majorant;
            if (t >= t1) return true;
            if (uniform(random) * majorant < medium_.extinction(ray.origin + ray.direction * t)) {
                collision = t;
                return false;
            }
        }
    });
    return collision;
}

double CloudPathTracer::transmittance(const MediumRay& ray, double tMax, std::mt19937_64& random) const {
    double estimate = 1.0;
    medium_.majorants(ray, tMax, [&](double t0, double t1, double majorant) {
        double t = t0;
        for (;;) {
            t -= std::log(1.0 - uniform(random)) / majorant;
            if (t >= t1) return true;
            estimate *= std::max(0.0, 1.0 - medium_.extinction(ray.origin + ray.direction * t) / majorant);
            // Russian roulette on a small estimate: unbiased, and it ends long shadow rays.
            if (estimate < 0.1) {
                if (uniform(random) >= 0.5) {
                    estimate = 0.0;
                    return false;
                }
                estimate *= 2.0;
            }
        }
    });
    return estimate;
}

double CloudPathTracer::groundDistance(const MediumRay& ray) const {
    if (!lighting_.groundHeight || ray.direction.y >= 0.0 || ray.origin.y <= *lighting_.groundHeight) return kInfinity;
    return (*lighting_.groundHeight - ray.origin.y) / ray.direction.y;
}

glm::dvec3 CloudPathTracer::radiance(const MediumRay& start, std::mt19937_64& random, int* events) const {
    glm::dvec3 result(0.0), throughput(1.0);
    MediumRay ray = start;
    const auto counted = [&](int order) { return order >= settings_.firstOrder && order <= settings_.lastOrder; };
    // The sun's transmittance from p (the ground, when there is one, hides a sun below it).
    const auto sunTransmittance = [&](glm::dvec3 p) {
        const MediumRay toSun{p, lighting_.toSun};
        return groundDistance(toSun) < kInfinity ? 0.0 : transmittance(toSun, kInfinity, random);
    };
    int order = 0;
    while (order < kBounceLimit) {
        const double ground = groundDistance(ray);
        const std::optional<double> collision = freeFlight(ray, ground, random);
        if (!collision && ground == kInfinity) {
            if (counted(order)) result += throughput * sky(ray.direction);
            break;
        }
        const double t = collision ? *collision : ground;
        const glm::dvec3 p = ray.origin + ray.direction * t;
        ++order;
        glm::dvec3 next;
        if (collision) {
            // In the medium: the sun through the phase function, then a direction drawn from it.
            throughput *= settings_.albedo;
            if (counted(order)) {
                const double phase = henyeyGreensteinPhase(glm::dot(lighting_.toSun, ray.direction), settings_.asymmetry);
                result += throughput * lighting_.sunIrradiance * (phase * sunTransmittance(p));
            }
            next = sampleHenyeyGreenstein(ray.direction, settings_.asymmetry, uniform(random), uniform(random));
        } else {
            // On the ground: Lambert's albedo / pi times the sun's irradiance on it, then a
            // direction drawn by the cosine.
            const glm::dvec3 normal(0.0, 1.0, 0.0);
            throughput *= lighting_.groundAlbedo;
            const double cosine = glm::dot(normal, lighting_.toSun);
            if (counted(order) && cosine > 0.0) result += throughput * lighting_.sunIrradiance * (cosine / kPi * sunTransmittance(p));
            const double u = uniform(random);
            next = around(normal, std::sqrt(1.0 - u), 2.0 * kPi * uniform(random));
        }
        if (order >= settings_.lastOrder) break;
        if (order >= settings_.rouletteFrom) {
            const double survive = std::min(1.0, std::max({throughput.x, throughput.y, throughput.z}));
            if (survive <= 0.0 || uniform(random) >= survive) break;
            throughput /= survive;
        }
        if (std::max({throughput.x, throughput.y, throughput.z}) <= 0.0) break;
        ray = {p, next};
    }
    if (events) *events = order;
    return result;
}

glm::dvec3 CloudPathTracer::meanRadiance(const MediumRay& ray, int paths, std::mt19937_64& random) const {
    glm::dvec3 sum(0.0);
    for (int k = 0; k < paths; ++k) sum += radiance(ray, random);
    return sum / static_cast<double>(std::max(paths, 1));
}

}  // namespace firmament
