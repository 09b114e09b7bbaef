#include "atmosphere/hillaire/HillaireParameterization.h"

#include <algorithm>
#include <cmath>

namespace firmament::atmosphere::hillaire {

namespace {
constexpr double kPi = 3.14159265358979323846;

// rho^2 = r^2 - Rg^2, as (r - Rg)(r + Rg): the GPU's single precision keeps the altitude's digits
// that way, where r^2 - Rg^2 would cancel them.
double horizonDistanceSquared(const AtmosphereParameters& p, double r) { return std::max((r - p.earthRadius) * (r + p.earthRadius), 0.0); }
}  // namespace

Dimensions Dimensions::of(LutResolution resolution) {
    Dimensions d;
    switch (resolution) {
        case LutResolution::Small: d.transmittanceMu = 64, d.transmittanceR = 16, d.multipleScatteringMuS = 16, d.multipleScatteringR = 16; break;
        case LutResolution::Medium: d.transmittanceMu = 128, d.transmittanceR = 32; break;
        case LutResolution::Full: break;
    }
    return d;
}

double unitToTexture(double u, int n) { return 0.5 / n + u * (1.0 - 1.0 / n); }
double textureToUnit(double x, int n) { return (x - 0.5 / n) / (1.0 - 1.0 / n); }

// The far root of |x + d v| = Rt for a ray from radius r along the zenith cosine mu.
double distanceToTop(const AtmosphereParameters& p, double r, double mu) {
    const double top = p.topRadius();
    const double discriminant = std::max(r * r * (mu * mu - 1.0) + top * top, 0.0);
    return std::max(-r * mu + std::sqrt(discriminant), 0.0);
}

glm::dvec2 transmittanceUnit(const AtmosphereParameters& p, double r, double mu) {
    const double H = std::sqrt(horizonDistanceSquared(p, p.topRadius()));
    const double rho = std::sqrt(horizonDistanceSquared(p, r));
    const double dMin = p.topRadius() - r, dMax = rho + H;
    const double d = distanceToTop(p, r, mu);
    const double xMu = dMax > dMin ? (d - dMin) / (dMax - dMin) : 0.0;
    return {std::clamp(xMu, 0.0, 1.0), std::clamp(rho / H, 0.0, 1.0)};
}

RadiusAndCosine transmittanceCoordinates(const AtmosphereParameters& p, glm::dvec2 unit) {
    const double H = std::sqrt(horizonDistanceSquared(p, p.topRadius()));
    const double rho = H * unit.y;
    RadiusAndCosine c;
    c.r = std::sqrt(rho * rho + p.earthRadius * p.earthRadius);
    const double dMin = p.topRadius() - c.r, dMax = rho + H;
    const double d = dMin + unit.x * (dMax - dMin);
    // The law of cosines in the triangle of the centre, x and the exit point: Rt^2 = r^2 + d^2 + 2 r d mu.
    c.mu = d == 0.0 ? 1.0 : std::clamp((H * H - rho * rho - d * d) / (2.0 * c.r * d), -1.0, 1.0);
    return c;
}

glm::dvec2 multipleScatteringUnit(const AtmosphereParameters& p, double r, double muS) {
    return {std::clamp(0.5 + 0.5 * muS, 0.0, 1.0), std::clamp((r - p.earthRadius) / p.atmosphereHeight, 0.0, 1.0)};
}

RadiusAndCosine multipleScatteringCoordinates(const AtmosphereParameters& p, glm::dvec2 unit) {
    return {p.earthRadius + unit.y * p.atmosphereHeight, 2.0 * unit.x - 1.0};
}

double horizonZenithAngle(const AtmosphereParameters& p, double r) {
    const double cosBeta = std::sqrt(horizonDistanceSquared(p, r)) / r;
    return kPi - std::acos(std::clamp(cosBeta, 0.0, 1.0));
}

glm::dvec2 skyViewUnit(const AtmosphereParameters& p, double r, double mu, double cosAzimuth) {
    const double horizon = horizonZenithAngle(p, r), beta = kPi - horizon;
    const double theta = std::acos(std::clamp(mu, -1.0, 1.0));
    double v;
    if (theta < horizon)
        v = 0.5 * (1.0 - std::sqrt(1.0 - theta / horizon));
    else
        v = 0.5 * (1.0 + std::sqrt(std::clamp((theta - horizon) / beta, 0.0, 1.0)));
    const double u = std::sqrt(std::clamp(0.5 - 0.5 * cosAzimuth, 0.0, 1.0));
    return {u, v};
}

SkyViewDirection skyViewDirection(const AtmosphereParameters& p, double r, glm::dvec2 unit) {
    const double horizon = horizonZenithAngle(p, r), beta = kPi - horizon;
    double theta;
    if (unit.y < 0.5) {
        const double s = 1.0 - 2.0 * unit.y;  // sqrt(1 - theta / horizon)
        theta = horizon * (1.0 - s * s);
    } else {
        const double s = 2.0 * unit.y - 1.0;  // sqrt((theta - horizon) / beta)
        theta = horizon + beta * s * s;
    }
    return {std::cos(theta), 1.0 - 2.0 * unit.x * unit.x};
}

double aerialPerspectiveUnit(double distance) { return std::clamp(distance / kAerialPerspectiveDepth, 0.0, 1.0); }
double aerialPerspectiveDistance(double unit) { return unit * kAerialPerspectiveDepth; }

}  // namespace firmament::atmosphere::hillaire
