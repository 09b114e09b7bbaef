#include "atmosphere/yusov/YusovParameterization.h"

#include <algorithm>
#include <cmath>

namespace firmament::atmosphere {

namespace {
constexpr double kPi = 3.14159265358979323846;
constexpr double kViewZenithPower = 0.2;     // eq. 5
constexpr double kSunZenithMinCos = -0.1975;  // eq. 6
const double kSunZenithTanScale = std::tan(1.26 * 1.1);
constexpr double kSunViewPower = 1.5;        // eq. 7

double saturate(double x) { return std::clamp(x, 0.0, 1.0); }
}  // namespace

double cosHorizon(const AtmosphereParameters& p, double h) {
    h = std::max(h, 0.0);
    return -std::sqrt(h * (2.0 * p.earthRadius + h)) / (p.earthRadius + h);
}

UnitCoordinates toUnit(const AtmosphereParameters& p, const ScatteringCoordinates& c) {
    return toUnit(p, c, c.cosView > cosHorizon(p, c.altitude));
}

UnitCoordinates toUnit(const AtmosphereParameters& p, const ScatteringCoordinates& c, bool above) {
    UnitCoordinates u;
    u.altitude = std::sqrt(saturate(c.altitude / p.atmosphereHeight));  // eq. 4
    const double ch = cosHorizon(p, c.altitude);                          // eq. 5
    const double t = above ? (c.cosView - ch) / (1.0 - ch) : (ch - c.cosView) / (ch + 1.0);
    u.viewZenith = std::pow(saturate(t), kViewZenithPower);
    u.aboveHorizon = above;
    // eq. 6, as Bruneton implements it (see the shader for the document's misplaced bracket).
    u.sunZenith = saturate(0.5 * (std::atan(std::max(c.cosSun, kSunZenithMinCos) * kSunZenithTanScale) / 1.1 + 0.74));
    const double gamma = std::acos(std::clamp(c.cosSunView, -1.0, 1.0)) / kPi;  // eq. 7
    u.sunView = 0.5 + 0.5 * (gamma >= 0.5 ? 1.0 : -1.0) * std::pow(std::abs(2.0 * (gamma - 0.5)), kSunViewPower);
    return u;
}

ScatteringCoordinates fromUnit(const AtmosphereParameters& p, const UnitCoordinates& u) {
    ScatteringCoordinates c;
    c.altitude = u.altitude * u.altitude * p.atmosphereHeight;
    const double ch = cosHorizon(p, c.altitude);
    const double t = std::pow(saturate(u.viewZenith), 1.0 / kViewZenithPower);
    c.cosView = u.aboveHorizon ? ch + t * (1.0 - ch) : ch - t * (ch + 1.0);
    c.cosSun = std::tan((2.0 * u.sunZenith - 0.74) * 1.1) / kSunZenithTanScale;
    const double gamma = 0.5 + 0.5 * (u.sunView >= 0.5 ? 1.0 : -1.0) * std::pow(std::abs(2.0 * (u.sunView - 0.5)), 1.0 / kSunViewPower);
    c.cosSunView = std::cos(gamma * kPi);
    return c;
}

double clampSunView(double cosView, double cosSun, double cosSunView) {
    const double sines = std::sqrt(saturate(1.0 - cosView * cosView) * saturate(1.0 - cosSun * cosSun));
    return std::clamp(cosSunView, cosView * cosSun - sines, cosView * cosSun + sines);
}

ScatteringCoordinates texelToWorld(const AtmosphereParameters& p, glm::ivec3 texel) {
    const LutDimensions& n = p.lut;
    const int halfView = n.viewZenith / 2;
    UnitCoordinates u;
    u.altitude = texel.x / (n.height - 1.0);
    u.aboveHorizon = texel.y >= halfView;
    u.viewZenith = (u.aboveHorizon ? texel.y - halfView : texel.y) / (halfView - 1.0);
    u.sunZenith = (texel.z % n.sunZenith) / (n.sunZenith - 1.0);
    u.sunView = (texel.z / n.sunZenith) / (n.sunView - 1.0);
    ScatteringCoordinates c = fromUnit(p, u);
    c.cosSunView = clampSunView(c.cosView, c.cosSun, c.cosSunView);
    return c;
}

}  // namespace firmament::atmosphere
