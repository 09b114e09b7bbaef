#include "clouds/SlabDoubling.h"

#include "core/Error.h"

#include <cmath>
#include <string>
#include <utility>

namespace firmament {

namespace {
constexpr double kPi = 3.14159265358979323846;
// The thinnest layer's scaled optical thickness, where doubling starts: single scattering is
// exact in it, and what it leaves out (light scattered twice) is of the order of its thickness.
constexpr double kStartThickness = 1.0 / 1073741824.0;  // 2^-30

using Matrix = std::vector<double>;  // n x n, row-major

Matrix multiply(const Matrix& a, const Matrix& b, size_t n) {
    Matrix c(n * n, 0.0);
    for (size_t i = 0; i < n; ++i)
        for (size_t k = 0; k < n; ++k) {
            const double aik = a[i * n + k];
            if (aik == 0.0) continue;
            for (size_t j = 0; j < n; ++j) c[i * n + j] += aik * b[k * n + j];
        }
    return c;
}

std::vector<double> apply(const Matrix& a, const std::vector<double>& x, size_t n) {
    std::vector<double> y(n, 0.0);
    for (size_t i = 0; i < n; ++i)
        for (size_t j = 0; j < n; ++j) y[i] += a[i * n + j] * x[j];
    return y;
}

// (I - a)^(-1) by Gauss-Jordan elimination with partial pivoting. The bounces between two layers
// that scatter and absorb nothing: finite while either lets some light through.
Matrix bounces(const Matrix& a, size_t n) {
    Matrix m(n * n), inverse(n * n, 0.0);
    for (size_t i = 0; i < n; ++i) {
        for (size_t j = 0; j < n; ++j) m[i * n + j] = (i == j ? 1.0 : 0.0) - a[i * n + j];
        inverse[i * n + i] = 1.0;
    }
    for (size_t c = 0; c < n; ++c) {
        size_t pivot = c;
        for (size_t r = c + 1; r < n; ++r)
            if (std::abs(m[r * n + c]) > std::abs(m[pivot * n + c])) pivot = r;
        if (m[pivot * n + c] == 0.0) throw Error("slab doubling: the layers' bounces do not converge (a singular matrix)");
        if (pivot != c)
            for (size_t j = 0; j < n; ++j) {
                std::swap(m[c * n + j], m[pivot * n + j]);
                std::swap(inverse[c * n + j], inverse[pivot * n + j]);
            }
        const double scale = 1.0 / m[c * n + c];
        for (size_t j = 0; j < n; ++j) {
            m[c * n + j] *= scale;
            inverse[c * n + j] *= scale;
        }
        for (size_t r = 0; r < n; ++r) {
            if (r == c || m[r * n + c] == 0.0) continue;
            const double factor = m[r * n + c];
            for (size_t j = 0; j < n; ++j) {
                m[r * n + j] -= factor * m[c * n + j];
                inverse[r * n + j] -= factor * inverse[c * n + j];
            }
        }
    }
    return inverse;
}

// Legendre polynomials P_0..P_{count-1} at x.
std::vector<double> legendre(double x, int count) {
    std::vector<double> p(static_cast<size_t>(count), 0.0);
    if (count > 0) p[0] = 1.0;
    if (count > 1) p[1] = x;
    for (int l = 2; l < count; ++l) p[l] = ((2.0 * l - 1.0) * x * p[l - 1] - (l - 1.0) * p[l - 2]) / l;
    return p;
}

// The integral over [0, d] of e^(-t a) e^(-(d - t) b), the path of light entering a layer of
// thickness d at one secant (a) and leaving at another (b), scattered once at t.
double onceThrough(double d, double a, double b) {
    const double x = (a - b) * d;
    if (std::abs(x) < 1e-8) return d * std::exp(-b * d) * (1.0 - 0.5 * x);
    return (std::exp(-b * d) - std::exp(-a * d)) / (a - b);
}
}  // namespace

void gaussLegendreUnit(int n, std::vector<double>& nodes, std::vector<double>& weights) {
    nodes.assign(static_cast<size_t>(n), 0.0);
    weights.assign(static_cast<size_t>(n), 0.0);
    for (int i = 0; i < n; ++i) {
        double x = std::cos(kPi * (i + 0.75) / (n + 0.5));  // Newton from Tricomi's estimate
        double derivative = 1.0;
        for (int iteration = 0; iteration < 100; ++iteration) {
            double p0 = 1.0, p1 = x;
            for (int l = 2; l <= n; ++l) {
                const double p2 = ((2.0 * l - 1.0) * x * p1 - (l - 1.0) * p0) / l;
                p0 = p1;
                p1 = p2;
            }
            if (n == 1) p0 = 1.0;
            derivative = n * (x * p1 - p0) / (x * x - 1.0);
            const double step = p1 / derivative;
            x -= step;
            if (std::abs(step) < 1e-15) break;
        }
        // On [-1, 1] the weight is 2 / ((1 - x^2) P'(x)^2); mapped to [0, 1], half of it.
        nodes[static_cast<size_t>(i)] = 0.5 * (1.0 - x);
        weights[static_cast<size_t>(i)] = 1.0 / ((1.0 - x * x) * derivative * derivative);
    }
}

SlabDoubling::SlabDoubling(double asymmetry, int gaussPerHemisphere, std::vector<double> viewingCosines) {
    if (gaussPerHemisphere < 1) throw Error("slab doubling: at least one Gauss node per hemisphere");
    gaussLegendreUnit(gaussPerHemisphere, cosines_, weights_);
    for (const double c : viewingCosines) {
        if (!(c > 0.0 && c <= 1.0)) throw Error("slab doubling: a viewing direction's cosine must lie in (0, 1], not " + std::to_string(c));
        cosines_.push_back(c);
        weights_.push_back(0.0);
    }
    const int streams = 2 * gaussPerHemisphere;
    truncation_ = std::pow(asymmetry, streams);
    moments_.resize(static_cast<size_t>(streams));
    for (int l = 0; l < streams; ++l) moments_[static_cast<size_t>(l)] = (std::pow(asymmetry, l) - truncation_) / (1.0 - truncation_);
    const size_t n = cosines_.size();
    std::vector<std::vector<double>> p(n);
    for (size_t i = 0; i < n; ++i) p[i] = legendre(cosines_[i], streams);
    phaseSame_.assign(n * n, 0.0);
    phaseOpposite_.assign(n * n, 0.0);
    for (size_t i = 0; i < n; ++i)
        for (size_t j = 0; j < n; ++j)
            for (int l = 0; l < streams; ++l) {
                const double term = (2.0 * l + 1.0) * moments_[static_cast<size_t>(l)] * p[i][static_cast<size_t>(l)] * p[j][static_cast<size_t>(l)];
                phaseSame_[i * n + j] += term;
                phaseOpposite_[i * n + j] += (l % 2 ? -term : term);  // P_l(-x) = (-1)^l P_l(x)
            }
}

double SlabDoubling::scaledPhase(double cosine) const {
    const std::vector<double> p = legendre(cosine, static_cast<int>(moments_.size()));
    double sum = 0.0;
    for (size_t l = 0; l < moments_.size(); ++l) sum += (2.0 * l + 1.0) * moments_[l] * p[l];
    return sum;
}

SlabDoubling::Layer SlabDoubling::layer(double thickness) const {
    const double scaledThickness = (1.0 - truncation_) * thickness;
    const size_t n = cosines_.size();
    Layer layer;
    layer.reflection.assign(n * n, 0.0);
    layer.transmission.assign(n * n, 0.0);
    layer.outTop.assign(n, 0.0);
    layer.outBottom.assign(n, 0.0);
    if (scaledThickness <= 0.0) {
        for (size_t i = 0; i < n; ++i) layer.transmission[i * n + i] = 1.0;
        return layer;
    }
    int doublings = 0;
    double d = scaledThickness;
    while (d > kStartThickness) {
        d *= 0.5;
        ++doublings;
    }
    // The thin layer: single scattering, exactly (the source (w_j / 2) p0 I_j per unit depth).
    for (size_t i = 0; i < n; ++i) {
        const double a = 1.0 / cosines_[i];
        for (size_t j = 0; j < n; ++j) {
            const double b = 1.0 / cosines_[j], source = 0.5 * weights_[j];
            layer.reflection[i * n + j] = source * phaseOpposite_[i * n + j] * a * (1.0 - std::exp(-(a + b) * d)) / (a + b);
            layer.transmission[i * n + j] = source * phaseSame_[i * n + j] * a * onceThrough(d, b, a);
        }
        layer.transmission[i * n + i] += std::exp(-a * d);
        layer.outTop[i] = scaledPhase(-cosines_[i]) / (4.0 * kPi) * a * (1.0 - std::exp(-(a + 1.0) * d)) / (a + 1.0);
        layer.outBottom[i] = scaledPhase(cosines_[i]) / (4.0 * kPi) * a * onceThrough(d, 1.0, a);
    }
    layer.beam = std::exp(-d);
    for (int k = 0; k < doublings; ++k) {
        // Two copies, one over the other: D, the light down between them, = G (T x) with
        // G = (I - R R)^(-1); up between them R D.
        const Matrix g = bounces(multiply(layer.reflection, layer.reflection, n), n);
        const Matrix gt = multiply(g, layer.transmission, n);
        const Matrix rgt = multiply(layer.reflection, gt, n);
        Matrix reflection = multiply(layer.transmission, rgt, n);
        for (size_t i = 0; i < n * n; ++i) reflection[i] += layer.reflection[i];
        Matrix transmission = multiply(layer.transmission, gt, n);
        // The beam: diffuse light down between them from the upper copy, and the lower copy's
        // (lit by the beam through the upper) reflected up into it.
        std::vector<double> source = apply(layer.reflection, layer.outTop, n);
        for (size_t i = 0; i < n; ++i) source[i] = layer.outBottom[i] + layer.beam * source[i];
        const std::vector<double> down = apply(g, source, n);
        std::vector<double> up = apply(layer.reflection, down, n);
        for (size_t i = 0; i < n; ++i) up[i] += layer.beam * layer.outTop[i];
        const std::vector<double> outTop = apply(layer.transmission, up, n), outBottom = apply(layer.transmission, down, n);
        for (size_t i = 0; i < n; ++i) {
            layer.outTop[i] += outTop[i];
            layer.outBottom[i] = layer.beam * layer.outBottom[i] + outBottom[i];
        }
        layer.reflection = std::move(reflection);
        layer.transmission = std::move(transmission);
        layer.beam *= layer.beam;
    }
    return layer;
}

SlabDoubling::Field SlabDoubling::diffuse(double depth, double total) const {
    return between(layer(depth), layer(total - depth));
}

SlabDoubling::Field SlabDoubling::between(const Layer& above, const Layer& below) const {
    const size_t n = cosines_.size();
    // Between them: down D = G (out of the upper's bottom + the lower's top light reflected back
    // down by the upper), up U = the lower's top light + R_below D.
    const Matrix g = bounces(multiply(above.reflection, below.reflection, n), n);
    std::vector<double> source = apply(above.reflection, below.outTop, n);
    for (size_t i = 0; i < n; ++i) source[i] = above.outBottom[i] + above.beam * source[i];
    Field field;
    field.down = apply(g, source, n);
    field.up = apply(below.reflection, field.down, n);
    for (size_t i = 0; i < n; ++i) field.up[i] += above.beam * below.outTop[i];
    return field;
}

SlabDoubling::Field SlabDoubling::singleScattering(double depth, double total) const {
    const size_t n = cosines_.size();
    const double t = (1.0 - truncation_) * depth, T = (1.0 - truncation_) * total;
    Field field;
    field.down.resize(n);
    field.up.resize(n);
    for (size_t i = 0; i < n; ++i) {
        const double m = cosines_[i], a = 1.0 / m;
        // Down: scattered at t' in [0, t], carried t - t' at secant a: a e^(-t) ... = a onceThrough(t, 1, a).
        field.down[i] = scaledPhase(m) / (4.0 * kPi) * a * onceThrough(t, 1.0, a);
        // Up: scattered at t' in [t, T], carried t' - t.
        field.up[i] = scaledPhase(-m) / (4.0 * kPi) * (std::exp(-t) - std::exp(-T - (T - t) * a)) / (1.0 + m);
    }
    return field;
}

double SlabDoubling::flux(const std::vector<double>& radiance) const {
    double sum = 0.0;
    for (size_t i = 0; i < radiance.size(); ++i) sum += weights_[i] * cosines_[i] * radiance[i];
    return 2.0 * kPi * sum;
}

}  // namespace firmament
