#include "reference/ReferenceAtmosphere.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <vector>

namespace firmament::atmosphere {

namespace {

constexpr double kPi = 3.14159265358979323846;

// Nodes and weights of 8-point Gauss-Legendre quadrature on [-1, 1] (positive half).
constexpr std::array<double, 4> kNodes{0.1834346424956498, 0.5255324099163290, 0.7966664774136267, 0.9602898564975363};
constexpr std::array<double, 4> kWeights{0.3626837833783620, 0.3137066458778873, 0.2223810344533745, 0.1012285362903763};

constexpr int kDensitySegments = 32;   // per net-density integral
constexpr int kScatteringSegments = 48;  // per lit interval of the view ray

// Distances (near, far) along start + t dir to a sphere about the origin; nullopt-like: far < near.
glm::dvec2 raySphere(glm::dvec3 start, glm::dvec3 dir, double radius) {
    const double b = glm::dot(start, dir);
    const double c = glm::dot(start, start) - radius * radius;
    const double discriminant = b * b - c;
    if (discriminant < 0.0) return {1.0, -1.0};
    const double root = std::sqrt(discriminant);
    return {-b - root, -b + root};
}

}  // namespace

double gaussLegendre(const std::function<double(double)>& f, double a, double b, int segments) {
    return gaussLegendre3([&](double s) { return glm::dvec3(f(s)); }, a, b, segments).x;
}

glm::dvec3 gaussLegendre3(const std::function<glm::dvec3(double)>& f, double a, double b, int segments) {
    glm::dvec3 sum(0.0);
    const double width = (b - a) / segments;
    for (int i = 0; i < segments; ++i) {
        const double centre = a + (i + 0.5) * width, half = 0.5 * width;
        for (size_t k = 0; k < kNodes.size(); ++k)
            sum += kWeights[k] * half * (f(centre - half * kNodes[k]) + f(centre + half * kNodes[k]));
    }
    return sum;
}

double rayleighPhase(double mu) { return 3.0 / (16.0 * kPi) * (1.0 + mu * mu); }

double miePhase(double mu, double g) {
    const double g2 = g * g;
    return 3.0 / (8.0 * kPi) * (1.0 - g2) * (1.0 + mu * mu) / ((2.0 + g2) * std::pow(1.0 + g2 - 2.0 * g * mu, 1.5));
}

glm::dvec3 ReferenceAtmosphere::density(double h) const {
    const double ozone = std::max(0.0, 1.0 - std::abs(h - p_.ozoneCentre) / p_.ozoneHalfWidth);
    return {std::exp(-h / p_.rayleighScaleHeight), std::exp(-h / p_.mieScaleHeight), ozone};
}

glm::dvec3 ReferenceAtmosphere::netDensity(glm::dvec3 from, glm::dvec3 to) const {
    const double length = glm::length(to - from);
    if (length <= 0.0) return glm::dvec3(0.0);
    const glm::dvec3 dir = (to - from) / length;
    return gaussLegendre3([&](double s) { return density(glm::length(from + dir * s) - p_.earthRadius); }, 0.0, length,
                          kDensitySegments);
}

glm::dvec3 ReferenceAtmosphere::netDensityToTop(double h, double cosZenith) const {
    const glm::dvec3 start(0.0, p_.earthRadius + h, 0.0);
    const glm::dvec3 dir(std::sqrt(std::max(0.0, 1.0 - cosZenith * cosZenith)), cosZenith, 0.0);
    const double toTop = std::max(raySphere(start, dir, p_.topRadius()).y, 0.0);
    return netDensity(start, start + dir * toTop);
}

glm::dvec3 ReferenceAtmosphere::opticalDepth(glm::dvec3 net) const {
    return p_.rayleighScattering * net.x + p_.mieExtinction * net.y + p_.ozoneAbsorption * net.z;
}

bool ReferenceAtmosphere::inEarthShadow(glm::dvec3 position, glm::dvec3 sunDir) const { return hitsGround(position, sunDir); }

glm::dvec3 ReferenceAtmosphere::sunTransmittance(glm::dvec3 position, glm::dvec3 sunDir) const {
    if (inEarthShadow(position, sunDir)) return glm::dvec3(0.0);
    const double toTop = std::max(raySphere(position, sunDir, p_.topRadius()).y, 0.0);
    return glm::exp(-opticalDepth(netDensity(position, position + sunDir * toTop)));
}

bool ReferenceAtmosphere::hitsGround(glm::dvec3 start, glm::dvec3 dir) const {
    const double radius = glm::length(start);
    return glm::dot(start / radius, dir) < cosHorizon(p_, radius - p_.earthRadius);
}

double ReferenceAtmosphere::rayLength(glm::dvec3 start, glm::dvec3 dir) const { return rayLength(start, dir, hitsGround(start, dir)); }

double ReferenceAtmosphere::rayLength(glm::dvec3 start, glm::dvec3 dir, bool ground) const {
    if (ground) {
        const double b = glm::dot(start, dir), c = glm::dot(start, start) - p_.earthRadius * p_.earthRadius;
        return std::max(-b - std::sqrt(std::max(b * b - c, 0.0)), 0.0);
    }
    return std::max(raySphere(start, dir, p_.topRadius()).y, 0.0);
}

glm::dvec3 ReferenceAtmosphere::singleScattering(glm::dvec3 start, glm::dvec3 viewDir, glm::dvec3 sunDir) const {
    return singleScattering(start, viewDir, sunDir, hitsGround(start, viewDir));
}

glm::dvec3 ReferenceAtmosphere::singleScattering(glm::dvec3 start, glm::dvec3 viewDir, glm::dvec3 sunDir, bool ground) const {
    const double cosTheta = glm::dot(viewDir, sunDir);
    const SpeciesScattering s = speciesScattering(start, viewDir, sunDir, ground);
    return s.rayleigh * rayleighPhase(cosTheta) + s.mie * miePhase(cosTheta, p_.mieAsymmetry);
}

ReferenceAtmosphere::SpeciesScattering ReferenceAtmosphere::singleScatteringBySpecies(const ScatteringCoordinates& c, bool aboveHorizon) const {
    const Ray r = ray(c);
    return speciesScattering(r.start, r.viewDir, r.sunDir, !aboveHorizon);
}

ReferenceAtmosphere::SpeciesScattering ReferenceAtmosphere::speciesScattering(glm::dvec3 start, glm::dvec3 viewDir, glm::dvec3 sunDir,
                                                                            bool ground) const {
    const double length = rayLength(start, viewDir, ground);
    // Where the ray crosses the boundary of the Earth's shadow: the cylinder of radius R
    // behind the Earth (|q - (q.l) l| = R with q.l < 0) and the plane q.l = 0 closing it.
    std::vector<double> cuts{0.0, length};
    const glm::dvec3 qPerp = start - glm::dot(start, sunDir) * sunDir;
    const glm::dvec3 vPerp = viewDir - glm::dot(viewDir, sunDir) * sunDir;
    const double a = glm::dot(vPerp, vPerp), b = 2.0 * glm::dot(qPerp, vPerp), c = glm::dot(qPerp, qPerp) - p_.earthRadius * p_.earthRadius;
    if (a > 0.0 && b * b - 4.0 * a * c > 0.0) {
        const double root = std::sqrt(b * b - 4.0 * a * c);
        cuts.push_back((-b - root) / (2.0 * a));
        cuts.push_back((-b + root) / (2.0 * a));
    }
    if (std::abs(glm::dot(viewDir, sunDir)) > 0.0) cuts.push_back(-glm::dot(start, sunDir) / glm::dot(viewDir, sunDir));
    std::erase_if(cuts, [&](double s) { return !(s >= 0.0 && s <= length); });
    std::sort(cuts.begin(), cuts.end());

    // Each lit stretch by composite Gauss-Legendre quadrature, its nodes visited in order along
    // the ray: the net density from the camera to a node is the previous node's plus one 8-point
    // rule over the short step between them (a step is under 1/48 of the stretch, where the
    // density's scale heights make the rule exact to rounding).
    const auto densityAt = [&](double s) { return density(glm::length(start + viewDir * s) - p_.earthRadius); };
    constexpr int kHalfNodes = static_cast<int>(kNodes.size());
    SpeciesScattering total{glm::dvec3(0.0), glm::dvec3(0.0)};
    for (size_t i = 0; i + 1 < cuts.size(); ++i) {
        const double s0 = cuts[i], s1 = cuts[i + 1];
        if (s1 - s0 <= 0.0 || inEarthShadow(start + viewDir * (0.5 * (s0 + s1)), sunDir)) continue;
        glm::dvec3 toNode = netDensity(start, start + viewDir * s0);
        double previous = s0;
        const double width = (s1 - s0) / kScatteringSegments, half = 0.5 * width;
        for (int segment = 0; segment < kScatteringSegments; ++segment) {
            const double centre = s0 + (segment + 0.5) * width;
            for (int n = 0; n < 2 * kHalfNodes; ++n) {
                // Nodes from the nearest to the farthest: -x_3, -x_2, ..., x_2, x_3.
                const auto k = static_cast<size_t>(n < kHalfNodes ? kHalfNodes - 1 - n : n - kHalfNodes);
                const double s = centre + (n < kHalfNodes ? -half : half) * kNodes[k];
                toNode += gaussLegendre3(densityAt, previous, s, 1);
                previous = s;
                const glm::dvec3 rho = densityAt(s);
                const glm::dvec3 light = kWeights[k] * half * glm::exp(-opticalDepth(toNode)) * sunTransmittance(start + viewDir * s, sunDir);
                total.rayleigh += p_.rayleighScattering * rho.x * light;
                total.mie += p_.mieScattering * rho.y * light;
            }
        }
    }
    return total;
}

namespace {
constexpr int kPathBins = 256;
}  // namespace

double ReferenceAtmosphere::sampleBins(const std::vector<double>& weights, double length, double u1, double u2, double& pdf) {
    const double width = length / static_cast<double>(weights.size());
    std::vector<double> cumulative(weights.size());
    double total = 0.0;
    for (size_t i = 0; i < weights.size(); ++i) cumulative[i] = total += weights[i];
    const auto bin = std::min<size_t>(static_cast<size_t>(std::lower_bound(cumulative.begin(), cumulative.end(), u1 * total) - cumulative.begin()),
                                      weights.size() - 1);
    pdf = weights[bin] / total / width;
    return (static_cast<double>(bin) + u2) * width;
}

double ReferenceAtmosphere::sampleByDensity(glm::dvec3 start, glm::dvec3 dir, double length, double u1, double u2, double& pdf) const {
    const double width = length / kPathBins;
    std::vector<double> weights(kPathBins);
    for (int i = 0; i < kPathBins; ++i) {
        const glm::dvec3 rho = density(glm::length(start + dir * ((i + 0.5) * width)) - p_.earthRadius);
        weights[static_cast<size_t>(i)] = rho.x + rho.y;
    }
    return sampleBins(weights, length, u1, u2, pdf);
}

double ReferenceAtmosphere::sampleTowardSunlight(glm::dvec3 start, glm::dvec3 dir, double length, glm::dvec3 sunDir, double u1, double u2,
                                                 double& pdf) const {
    const double width = length / kPathBins;
    std::vector<double> scatterers(kPathBins), lit(kPathBins);
    double allScatterers = 0.0, litScatterers = 0.0;
    for (int i = 0; i < kPathBins; ++i) {
        const glm::dvec3 middle = start + dir * ((i + 0.5) * width);
        const glm::dvec3 rho = density(glm::length(middle) - p_.earthRadius);
        scatterers[static_cast<size_t>(i)] = rho.x + rho.y;
        // Lit if any of it is: a line crosses the shadow's boundary at most twice, so a bin
        // whose ends and middle are all in the shadow is almost surely wholly in it. (A bin taken
        // as dark while part of it is lit keeps only the first density there: samples in that
        // part are rare and weigh hugely, and the estimate's variance is then unbounded.)
        const bool sunlit = !inEarthShadow(start + dir * (i * width), sunDir) || !inEarthShadow(middle, sunDir) ||
                            !inEarthShadow(start + dir * ((i + 1) * width), sunDir);
        lit[static_cast<size_t>(i)] = sunlit ? rho.x + rho.y : 0.0;
        allScatterers += scatterers[static_cast<size_t>(i)];
        litScatterers += lit[static_cast<size_t>(i)];
    }
    // Even shares of the density of scatterers, of the density where the sun is seen (when any
    // is), and of uniform distances: along a view in the Earth's shadow the light that reaches the
    // sunlit air comes from its thin upper part, which the density alone seldom draws.
    const double shares = litScatterers > 0.0 ? 3.0 : 2.0;
    std::vector<double> mixture(kPathBins);
    for (size_t i = 0; i < mixture.size(); ++i)
        mixture[i] = (scatterers[i] / allScatterers + (litScatterers > 0.0 ? lit[i] / litScatterers : 0.0) + 1.0 / kPathBins) / shares;
    return sampleBins(mixture, length, u1, u2, pdf);
}

namespace {
// A direction uniform over the sphere from two uniform numbers.
glm::dvec3 uniformDirection(double u1, double u2) {
    const double z = 1.0 - 2.0 * u1, phi = 2.0 * kPi * u2;
    const double r = std::sqrt(std::max(0.0, 1.0 - z * z));
    return {r * std::cos(phi), z, r * std::sin(phi)};
}

constexpr double kSunwardCone = 20.0 * kPi / 180.0;  // half-angle of the cone about the horizon towards the sun
}  // namespace

// An even mixture of directions uniform over the sphere and uniform in a cone of kSunwardCone
// about the horizon towards the sun: in twilight the air the sun still lights lies that way, low
// over the horizon, hundreds of kilometres off. pdf is the mixture's.
glm::dvec3 ReferenceAtmosphere::directionTowardSunlight(glm::dvec3 position, glm::dvec3 sunDir, std::mt19937_64& random, double& pdf) {
    std::uniform_real_distribution<double> unit(0.0, 1.0);
    const glm::dvec3 up = glm::normalize(position);
    const glm::dvec3 across = sunDir - glm::dot(sunDir, up) * up;
    const double coneSolidAngle = 2.0 * kPi * (1.0 - std::cos(kSunwardCone));
    const double choice = unit(random), u1 = unit(random), u2 = unit(random);  // in this order
    if (glm::dot(across, across) < 1e-12) {  // the sun at the zenith or the nadir: no horizon towards it
        pdf = 1.0 / (4.0 * kPi);
        return uniformDirection(u1, u2);
    }
    const glm::dvec3 axis = glm::normalize(across);
    glm::dvec3 w;
    if (choice < 0.5) {
        w = uniformDirection(u1, u2);
    } else {
        const double cosTheta = 1.0 - u1 * (1.0 - std::cos(kSunwardCone)), phi = 2.0 * kPi * u2;
        const double sinTheta = std::sqrt(std::max(0.0, 1.0 - cosTheta * cosTheta));
        const glm::dvec3 side = glm::cross(axis, up);
        w = axis * cosTheta + (up * std::cos(phi) + side * std::sin(phi)) * sinTheta;
    }
    pdf = 0.5 / (4.0 * kPi) + (glm::dot(w, axis) >= std::cos(kSunwardCone) ? 0.5 / coneSolidAngle : 0.0);
    return w;
}

glm::dvec3 ReferenceAtmosphere::tracePath(glm::dvec3 start, glm::dvec3 dir, glm::dvec3 sunDir, int minOrder, int maxOrder, PathSampling sampling,
                                          std::mt19937_64& random) const {
    std::uniform_real_distribution<double> unit(0.0, 1.0);
    const auto scattering = [&](glm::dvec3 rho, double cosTheta) {
        return p_.rayleighScattering * rho.x * rayleighPhase(cosTheta) + p_.mieScattering * rho.y * miePhase(cosTheta, p_.mieAsymmetry);
    };
    glm::dvec3 x = start, d = dir, throughput(1.0), contribution(0.0);
    for (int order = 1; order <= maxOrder; ++order) {
        const double length = rayLength(x, d);
        if (length <= 0.0) break;
        // The distance, in proportion to the density of scatterers along the segment (or the mixture).
        double pdf = 0.0;
        // Drawn second, then first: the order in which the first version's call, which passed
        // both draws as arguments, drew them under GCC (right to left), so that the Monte Carlo
        // tests' measured numbers stand.
        const double u2 = unit(random), u1 = unit(random);
        const double s = sampling == PathSampling::TowardSunlight ? sampleTowardSunlight(x, d, length, sunDir, u1, u2, pdf)
                                                                  : sampleByDensity(x, d, length, u1, u2, pdf);
        const glm::dvec3 p = x + d * s;
        const glm::dvec3 rho = density(glm::length(p) - p_.earthRadius);
        const glm::dvec3 reach = throughput / pdf * glm::exp(-opticalDepth(netDensity(x, p)));
        if (order >= minOrder) contribution += reach * scattering(rho, glm::dot(d, sunDir)) * sunTransmittance(p, sunDir);
        // The next segment looks along w, uniform over the sphere (pdf 1 / 4 pi), or from the
        // mixture that also aims at the sunlit air (directionTowardSunlight).
        double directionPdf = 1.0 / (4.0 * kPi);
        glm::dvec3 w;
        if (sampling == PathSampling::TowardSunlight) {
            w = directionTowardSunlight(p, sunDir, random, directionPdf);
        } else {
            const double z = unit(random);  // drawn in this order (a call may evaluate its arguments in any)
            const double phi = unit(random);
            w = uniformDirection(z, phi);
        }
        throughput = reach * scattering(rho, glm::dot(d, w)) / directionPdf;
        x = p;
        d = w;
    }
    return contribution;
}

namespace {
ReferenceAtmosphere::Estimate estimate(glm::dvec3 sum, glm::dvec3 sumOfSquares, int paths) {
    const glm::dvec3 mean = sum / static_cast<double>(paths);
    const glm::dvec3 variance = glm::max(sumOfSquares / static_cast<double>(paths) - mean * mean, 0.0);
    return {mean, glm::sqrt(variance / static_cast<double>(paths))};
}
}  // namespace

ReferenceAtmosphere::Estimate ReferenceAtmosphere::highOrderScattering(glm::dvec3 start, glm::dvec3 viewDir, glm::dvec3 sunDir,
                                                                     int maxOrder, int paths, unsigned seed, PathSampling sampling) const {
    return scatteringOrders(start, viewDir, sunDir, 2, maxOrder, paths, seed, sampling);
}

ReferenceAtmosphere::Estimate ReferenceAtmosphere::scatteringOrders(glm::dvec3 start, glm::dvec3 viewDir, glm::dvec3 sunDir, int minOrder,
                                                                  int maxOrder, int paths, unsigned seed, PathSampling sampling) const {
    std::mt19937_64 random(seed);
    glm::dvec3 sum(0.0), sumOfSquares(0.0);
    for (int path = 0; path < paths; ++path) {
        const glm::dvec3 contribution = tracePath(start, viewDir, sunDir, minOrder, maxOrder, sampling, random);
        sum += contribution;
        sumOfSquares += contribution * contribution;
    }
    return estimate(sum, sumOfSquares, paths);
}

ReferenceAtmosphere::Estimate ReferenceAtmosphere::skyIrradiance(glm::dvec3 position, glm::dvec3 sunDir, int maxOrder, int paths,
                                                                unsigned seed) const {
    std::mt19937_64 random(seed);
    std::uniform_real_distribution<double> unit(0.0, 1.0);
    const glm::dvec3 up = glm::normalize(position);
    const glm::dvec3 tangent = glm::normalize(glm::cross(up, std::abs(up.x) < 0.9 ? glm::dvec3(1.0, 0.0, 0.0) : glm::dvec3(0.0, 1.0, 0.0)));
    const glm::dvec3 bitangent = glm::cross(up, tangent);
    glm::dvec3 sum(0.0), sumOfSquares(0.0);
    for (int path = 0; path < paths; ++path) {
        // A direction in proportion to its cosine with the up vector (pdf cos / pi): the radiance
        // it brings, times pi, estimates the irradiance.
        const double u = unit(random), phi = 2.0 * kPi * unit(random);
        const double sine = std::sqrt(u);
        const glm::dvec3 w = tangent * (sine * std::cos(phi)) + bitangent * (sine * std::sin(phi)) + up * std::sqrt(std::max(0.0, 1.0 - u));
        const glm::dvec3 contribution = kPi * tracePath(position, w, sunDir, 1, maxOrder, PathSampling::ByDensity, random);
        sum += contribution;
        sumOfSquares += contribution * contribution;
    }
    return estimate(sum, sumOfSquares, paths);
}

glm::dvec3 ReferenceAtmosphere::singleScatteringIrradiance(glm::dvec3 position, glm::dvec3 sunDir, int directions) const {
    const double goldenAngle = kPi * (3.0 - std::sqrt(5.0));
    const glm::dvec3 up = glm::normalize(position);
    const glm::dvec3 tangent = glm::normalize(glm::cross(up, std::abs(up.x) < 0.9 ? glm::dvec3(1.0, 0.0, 0.0) : glm::dvec3(0.0, 1.0, 0.0)));
    const glm::dvec3 bitangent = glm::cross(up, tangent);
    glm::dvec3 sum(0.0);
    int used = 0;
    for (int i = 0; i < directions; ++i) {
        const double y = 1.0 - (2.0 * i + 1.0) / directions;  // the cosine with the up vector
        if (y <= 0.0) continue;
        const double r = std::sqrt(std::max(0.0, 1.0 - y * y));
        const glm::dvec3 w = tangent * (r * std::cos(goldenAngle * i)) + up * y + bitangent * (r * std::sin(goldenAngle * i));
        sum += singleScattering(position, w, sunDir) * y;
        ++used;
    }
    return sum * (2.0 * kPi / used);
}

ReferenceAtmosphere::Ray ReferenceAtmosphere::ray(const ScatteringCoordinates& c) const {
    Ray r;
    r.start = glm::dvec3(0.0, p_.earthRadius + c.altitude, 0.0);
    const double sinView = std::sqrt(std::max(0.0, 1.0 - c.cosView * c.cosView));
    r.viewDir = glm::dvec3(sinView, c.cosView, 0.0);
    const double cosSunView = clampSunView(c.cosView, c.cosSun, c.cosSunView);
    const double sunX = sinView > 1e-9 ? (cosSunView - c.cosView * c.cosSun) / sinView : 0.0;
    r.sunDir = glm::dvec3(sunX, c.cosSun, std::sqrt(std::max(0.0, 1.0 - sunX * sunX - c.cosSun * c.cosSun)));
    r.sunDir = glm::normalize(r.sunDir);
    return r;
}

glm::dvec3 ReferenceAtmosphere::singleScattering(const ScatteringCoordinates& c) const {
    const Ray r = ray(c);
    return singleScattering(r.start, r.viewDir, r.sunDir);
}

glm::dvec3 ReferenceAtmosphere::singleScattering(const ScatteringCoordinates& c, bool aboveHorizon) const {
    const Ray r = ray(c);
    return singleScattering(r.start, r.viewDir, r.sunDir, !aboveHorizon);
}

}  // namespace firmament::atmosphere
