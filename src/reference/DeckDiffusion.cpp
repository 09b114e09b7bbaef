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

}  // namespace firmament
