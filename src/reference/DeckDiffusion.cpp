#include "reference/DeckDiffusion.h"

#include <algorithm>
#include <cmath>

namespace firmament {

double deckDiffuseRadiance(double depth, double total, double mu, double g) {
    constexpr double kPi = 3.14159265358979323846;
    const double f = g * g, scaledG = (g - f) / (1.0 - f);
    const double t = (1.0 - f) * depth, T = (1.0 - f) * total;
    const double k = 3.0 / (4.0 * kPi);
    const double c1 = k * (5.0 - std::exp(-T)) / (4.0 + 3.0 * (1.0 - scaledG) * T);
    const double c0 = 5.0 / 3.0 * k - 2.0 / 3.0 * c1;
    const double i1 = c1 - k * std::exp(-t);
    const double i0 = c0 - (1.0 - scaledG) * c1 * t - k * std::exp(-t);
    return std::max(i0 + mu * i1, 0.0);
}

double deckSingleScattering(double depth, double total, double mu, double g) {
    constexpr double kPi = 3.14159265358979323846;
    const double f = g * g, scaledG = (g - f) / (1.0 - f);
    const double t = (1.0 - f) * depth, T = (1.0 - f) * total;
    const double phase = std::max(1.0 + 3.0 * scaledG * mu, 0.0) / (4.0 * kPi);
    const double m = std::abs(mu);
    double carried = 0.0;
    if (mu > 0.0)
        carried = std::abs(1.0 - mu) < 1e-3 ? t * std::exp(-t) : (std::exp(-t) - std::exp(-t / mu)) / (1.0 - mu);
    else
        carried = m < 1e-4 ? 0.0 : (std::exp(-t) - std::exp(-T - (T - t) / m)) / (1.0 + m);
    return phase * carried;
}

double deckMultipleScattering(double depth, double total, double mu, double g) {
    return std::max(deckDiffuseRadiance(depth, total, mu, g) - deckSingleScattering(depth, total, mu, g), 0.0);
}

namespace {
constexpr double kPi = 3.14159265358979323846;
}

DeckDiffusionCoordinates deckDiffusionCoordinates(const DeckDiffusionParameters& p, double depth, double total, double mu) {
    DeckDiffusionCoordinates c;
    c.x = std::acos(-std::clamp(mu, -1.0, 1.0)) / kPi * (p.cosines - 1);
    const double share = total > 0.0 ? std::clamp(depth / total, 0.0, 1.0) : 0.0;
    c.y = std::acos(1.0 - 2.0 * share) / kPi * (p.depths - 1);
    const double octaves = std::log2(std::max(total, 1e-30) / p.thinnest);
    c.z = std::clamp(octaves * p.thicknessesPerOctave, 0.0, p.thicknesses - 1.0);
    if (total < p.thinnest) c.scale = (total / p.thinnest) * (total / p.thinnest);
    return c;
}

double solvedSlabMultipleScattering(const DeckDiffusionTable& table, double depth, double total, double mu) {
    const DeckDiffusionParameters& p = table.parameters;
    const DeckDiffusionCoordinates c = deckDiffusionCoordinates(p, depth, total, mu);
    const int x0 = std::min(static_cast<int>(c.x), p.cosines - 2), y0 = std::min(static_cast<int>(c.y), p.depths - 2),
              z0 = std::min(static_cast<int>(c.z), p.thicknesses - 2);
    const double wx = c.x - x0, wy = c.y - y0, wz = c.z - z0;
    double sum = 0.0;
    for (int k = 0; k < 8; ++k) {
        const int dx = k & 1, dy = (k >> 1) & 1, dz = k >> 2;
        const double w = (dx ? wx : 1.0 - wx) * (dy ? wy : 1.0 - wy) * (dz ? wz : 1.0 - wz);
        sum += w * table.multiple[table.index(x0 + dx, y0 + dy, z0 + dz)];
    }
    return c.scale * sum;
}

}  // namespace firmament
