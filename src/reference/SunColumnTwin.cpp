#include "reference/SunColumnTwin.h"

#include "clouds/LightSpace.h"
#include "clouds/OpticalDepthTable.h"

#include <glm/geometric.hpp>

#include <algorithm>
#include <cmath>
#include <utility>

namespace firmament {

Chord chordThrough(const ModelParticle& q, glm::dvec3 origin, glm::dvec3 toSun, double earthRadius, ParticleDensityMethod method, int steps) {
    // The particle's frame: the planet's normal through its centre, and two tangents.
    const glm::dvec3 centre(q.centre);
    const glm::dvec3 normal = glm::normalize(centre + glm::dvec3(0.0, earthRadius, 0.0));
    const glm::dvec3 tangent = glm::normalize(glm::cross(normal, glm::dvec3(0.0, 0.0, 1.0))), bitangent = glm::cross(tangent, normal);
    const glm::dvec3 scale(q.horizontalRadius, q.verticalRadius, q.horizontalRadius);
    const glm::dvec3 offset = origin - centre;
    const glm::dvec3 o = glm::dvec3(glm::dot(offset, tangent), glm::dot(offset, normal), glm::dot(offset, bitangent)) / scale;
    const glm::dvec3 d = glm::dvec3(glm::dot(toSun, tangent), glm::dot(toSun, normal), glm::dot(toSun, bitangent)) / scale;
    const double a = glm::dot(d, d), b = glm::dot(o, d), c = glm::dot(o, o) - 1.0;
    const double discriminant = b * b - a * c;
    if (discriminant < 0.0) return {};
    const double root = std::sqrt(discriminant), near = (-b - root) / a, far = (-b + root) / a;
    const double length = far - std::max(near, 0.0);
    if (far <= 0.0 || length <= 0.0) return {};
    // The whole chord in unit-sphere space, turned by the particle's azimuth about y (as the GPU
    // adds it to the table's entry azimuth).
    glm::dvec3 entry = glm::normalize(o + near * d), through = glm::normalize(d);
    const double ca = std::cos(q.azimuth), sa = std::sin(q.azimuth);
    const auto turn = [&](glm::dvec3 v) { return glm::dvec3(v.x * ca - v.z * sa, v.y, v.x * sa + v.z * ca); };
    entry = turn(entry);
    through = turn(through);
    const double mean = meanChordDensity({glm::vec3(entry), glm::vec3(through)}, steps, method);
    return {std::max(near, 0.0), far, mean * length * q.density * kCloudExtinction};
}

double opticalDepthThrough(const ModelParticle& q, glm::dvec3 origin, glm::dvec3 toSun, double earthRadius, ParticleDensityMethod method, int steps) {
    return chordThrough(q, origin, toSun, earthRadius, method, steps).opticalDepth;
}

namespace {

// The optical depth of the chords that reach back to the particle's own chord, [0, ownEnd],
// without a gap longer than `gap`: their union grown from the particle outward, the chords taken
// by their start.
double deckDepth(std::vector<Chord> chords, double ownEnd, double gap) {
    std::sort(chords.begin(), chords.end(), [](const Chord& x, const Chord& y) { return x.start < y.start; });
    double reach = ownEnd, depth = 0.0;
    for (const Chord& chord : chords) {
        if (chord.start - gap > reach) break;
        reach = std::max(reach, chord.end);
        depth += chord.opticalDepth;
    }
    return depth;
}

}  // namespace

SunColumn sunColumn(const std::vector<ModelParticle>& particles, size_t index, glm::dvec3 toSun, double earthRadius, ParticleDensityMethod method,
                    double earlyExitDepth) {
    const glm::dvec3 origin(particles[index].centre);
    const double own = glm::dot(origin, toSun);
    // Every other particle by its distance towards the sun, nearest the sun first (the tile
    // lists' order); those as far as the particle itself are skipped, as the GPU skips them.
    std::vector<std::pair<double, size_t>> order;
    for (size_t k = 0; k < particles.size(); ++k) {
        const double toward = glm::dot(glm::dvec3(particles[k].centre), toSun);
        if (k != index && toward != own) order.emplace_back(toward, k);
    }
    std::sort(order.begin(), order.end(), [](const auto& x, const auto& y) { return x.first > y.first; });
    SunColumn column;
    std::vector<Chord> above, beyond;
    for (const auto& [toward, k] : order) {
        const bool nearer = toward > own;
        const Chord chord = chordThrough(particles[k], origin, nearer ? toSun : -toSun, earthRadius, method);
        if (chord.end <= chord.start) continue;  // missed
        (nearer ? column.above : column.beyond) += chord.opticalDepth;
        (nearer ? above : beyond).push_back(chord);
        if (earlyExitDepth > 0.0 && column.above + column.beyond > earlyExitDepth) break;
    }
    // The particle's own chord from its centre (as long towards the sun as away from it), and its
    // half-width across the sun's ray: the ellipsoid's in the vertical plane through the ray.
    const ModelParticle& p = particles[index];
    const double ownEnd = chordThrough(p, origin, toSun, earthRadius, method).end;
    const double sine = glm::dot(toSun, glm::normalize(origin + glm::dvec3(0.0, earthRadius, 0.0)));
    const double halfWidth = std::sqrt(double(p.horizontalRadius) * p.horizontalRadius * sine * sine +
                                       double(p.verticalRadius) * p.verticalRadius * (1.0 - sine * sine));
    column.deckAbove = deckDepth(std::move(above), ownEnd, kDeckGapShare * halfWidth);
    column.deckBeyond = deckDepth(std::move(beyond), ownEnd, kDeckGapShare * halfWidth);
    return column;
}

}  // namespace firmament
