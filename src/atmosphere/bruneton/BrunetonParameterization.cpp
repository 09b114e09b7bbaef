#include "atmosphere/bruneton/BrunetonParameterization.h"

#include <algorithm>
#include <cmath>

namespace firmament::atmosphere::bruneton {

namespace {
constexpr double kTransmittanceMuOffset = 0.15;  // the lowest zenith cosine of the transmittance table
constexpr double kTransmittanceAngle = 1.5;
constexpr double kIrradianceMuSOffset = 0.2;
constexpr double kMuSExponent = 3.0, kMuSOffset = 0.6;  // u_mu_s = (1 - exp(-3 mu_s - 0.6)) / (1 - exp(-3.6))
}  // namespace

Dimensions Dimensions::of(LutResolution resolution) {
    switch (resolution) {
        case LutResolution::Small: return {64, 16, 32, 8, 8, 32, 8, 4};
        case LutResolution::Medium: return {128, 32, 64, 16, 16, 64, 16, 8};
        case LutResolution::Full: return {256, 64, 64, 16, 32, 128, 32, 8};
    }
    return {};
}

double unitToTexture(double u, int n) { return 0.5 / n + u * (1.0 - 1.0 / n); }
double textureToUnit(double x, int n) { return (x - 0.5 / n) / (1.0 - 1.0 / n); }

glm::dvec2 transmittanceUnit(const AtmosphereParameters& p, double r, double mu) {
    const double ur = std::sqrt(std::clamp((r - p.earthRadius) / p.atmosphereHeight, 0.0, 1.0));
    const double umu = std::atan((mu + kTransmittanceMuOffset) / (1.0 + kTransmittanceMuOffset) * std::tan(kTransmittanceAngle)) /
                       kTransmittanceAngle;
    return {std::clamp(umu, 0.0, 1.0), ur};
}

Coordinates transmittanceCoordinates(const AtmosphereParameters& p, glm::dvec2 unit) {
    Coordinates c;
    c.r = p.earthRadius + unit.y * unit.y * p.atmosphereHeight;
    c.mu = -kTransmittanceMuOffset + std::tan(kTransmittanceAngle * unit.x) / std::tan(kTransmittanceAngle) * (1.0 + kTransmittanceMuOffset);
    return c;
}

glm::dvec2 irradianceUnit(const AtmosphereParameters& p, double r, double muS) {
    return {std::clamp((muS + kIrradianceMuSOffset) / (1.0 + kIrradianceMuSOffset), 0.0, 1.0),
            std::clamp((r - p.earthRadius) / p.atmosphereHeight, 0.0, 1.0)};
}

Coordinates irradianceCoordinates(const AtmosphereParameters& p, glm::dvec2 unit) {
    Coordinates c;
    c.r = p.earthRadius + unit.y * p.atmosphereHeight;
    c.muS = -kIrradianceMuSOffset + unit.x * (1.0 + kIrradianceMuSOffset);
    return c;
}

bool hitsGround(const AtmosphereParameters& p, double r, double mu) {
    const double ratio = p.earthRadius / r;
    return mu < -std::sqrt(std::max(0.0, 1.0 - ratio * ratio));
}

namespace {
// As parameterization.hlsli: distances from rho^2 = r^2 - Rg^2, free of cancellation.
double distanceToGround(double r, double mu, double rho2) {
    const double rmu = r * mu;
    return rho2 / std::max(-rmu + std::sqrt(std::max(rmu * rmu - rho2, 0.0)), 1e-3);
}
double distanceToTop(const AtmosphereParameters& p, double r, double mu) {
    const double rmu = r * mu;
    const double above = (p.topRadius() - r) * (p.topRadius() + r);
    const double root = std::sqrt(std::max(rmu * rmu + above, 0.0));
    return rmu > 0.0 ? above / std::max(rmu + root, 1e-3) : root - rmu;
}
}  // namespace

glm::dvec4 inscatterUnit(const AtmosphereParameters& p, const Dimensions& n, const Coordinates& c, bool groundHalf) {
    const double rg = p.earthRadius, rt = p.topRadius();
    const double horizonH = std::sqrt(rt * rt - rg * rg);
    const double h = std::max(c.r - rg, 0.0);
    const double rho2 = h * (2.0 * rg + h);
    const double rho = std::sqrt(rho2);
    const double r = rg + h;
    glm::dvec4 u;
    u.x = rho / horizonH;
    const double halfWidth = 0.5 - 1.0 / n.mu;  // the texture span of one half's texel centres
    if (groundHalf) u.y = 0.5 - 0.5 / n.mu - std::clamp(distanceToGround(r, c.mu, rho2) / std::max(rho, 1e-3), 0.0, 1.0) * halfWidth;
    else u.y = 0.5 + 0.5 / n.mu + std::clamp(distanceToTop(p, r, c.mu) / (rho + horizonH), 0.0, 1.0) * halfWidth;
    u.z = std::max((1.0 - std::exp(-kMuSExponent * c.muS - kMuSOffset)) / (1.0 - std::exp(-kMuSExponent - kMuSOffset)), 0.0);
    u.w = (1.0 + c.nu) * 0.5;
    return u;
}

Coordinates inscatterTexel(const AtmosphereParameters& p, const Dimensions& n, glm::ivec3 texel) {
    const double rg = p.earthRadius, rt = p.topRadius();
    const double horizonH = std::sqrt(rt * rt - rg * rg);
    Coordinates c;
    double rho = texel.z / (n.r - 1.0) * horizonH;
    const double h = std::clamp(rho * rho / (std::sqrt(rho * rho + rg * rg) + rg), kLowestLayer, p.atmosphereHeight - kHighestLayer);
    c.r = rg + h;
    const double rho2 = h * (2.0 * rg + h);
    rho = std::sqrt(rho2);
    const int half = n.mu / 2;
    if (texel.y < half) {  // to the ground: distances from r - Rg (straight down) to rho (the horizon)
        const double d = std::clamp((half - 1.0 - texel.y) / (half - 1.0) * rho, h, rho);
        c.mu = std::clamp(-(rho2 + d * d) / (2.0 * c.r * d), -1.0, 1.0);
    } else {  // to the top: distances from Rt - r (the zenith) to rho + H (the horizon)
        const double d = std::clamp((texel.y - half) / (half - 1.0) * (rho + horizonH), rt - c.r, rho + horizonH);
        c.mu = std::clamp((horizonH * horizonH - rho2 - d * d) / (2.0 * c.r * d), -1.0, 1.0);
    }
    const double umus = (texel.x % n.muS) / (n.muS - 1.0);
    c.muS = -(kMuSOffset + std::log(1.0 - umus * (1.0 - std::exp(-kMuSExponent - kMuSOffset)))) / kMuSExponent;
    c.muS = std::clamp(c.muS, -1.0, 1.0);
    const double nu = -1.0 + 2.0 * (texel.x / n.muS) / (n.nu - 1.0);
    const double sines = std::sqrt(std::max(0.0, (1.0 - c.mu * c.mu) * (1.0 - c.muS * c.muS)));
    c.nu = std::clamp(nu, c.mu * c.muS - sines, c.mu * c.muS + sines);
    return c;
}

}  // namespace firmament::atmosphere::bruneton
