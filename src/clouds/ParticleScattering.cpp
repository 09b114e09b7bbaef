#include "clouds/ParticleScattering.h"

#include "core/Error.h"
#include "core/ExrImage.h"
#include "tables/TableFileHeaders.h"

#include <glm/geometric.hpp>

#include <algorithm>
#include <cmath>
#include <cstdio>

namespace firmament {

namespace {
constexpr double kPi = 3.14159265358979323846;
const glm::dvec3 kSun(0.0, 0.0, 1.0);  // the direction towards the sun, in the particle's space
// Single scattering is cheap (no field to interpolate): 8 times the steps, so that texels where
// the sun's path shortens quickly along the view (the grazing, shadowed ones) converge too.
constexpr int kSingleStepsPerStep = 8;

// Distance from p (inside the unit sphere) along the unit direction d to the surface.
double distanceToSurface(glm::dvec3 p, glm::dvec3 d) {
    const double b = glm::dot(p, d), c = glm::dot(p, p) - 1.0;
    return -b + std::sqrt(std::max(b * b - c, 0.0));
}

// The sun's transmittance to p through a sphere of optical radius tau.
double sunTransmittance(double tau, glm::dvec3 point) { return std::exp(-tau * distanceToSurface(point, kSun)); }

// The field inside the sphere: radiance (or the source J) per (radius, point angle, direction
// zenith, direction azimuth), axially symmetric about the sun's direction.
class Field {
public:
    explicit Field(const ParticleScatteringParameters& p)
        : nr_(p.radii), np_(p.pointAngles), nz_(p.directionZeniths), na_(p.directionAzimuths), values_(static_cast<size_t>(nr_) * np_ * nz_ * na_, 0.0) {}

    double& at(int r, int p, int z, int a) { return values_[((static_cast<size_t>(r) * np_ + p) * nz_ + z) * na_ + a]; }
    double at(int r, int p, int z, int a) const { return values_[((static_cast<size_t>(r) * np_ + p) * nz_ + z) * na_ + a]; }

    // The cell's point (in the xz plane) and direction.
    glm::dvec3 point(int r, int p) const {
        const double radius = static_cast<double>(r) / (nr_ - 1), angle = (p + 0.5) / np_ * kPi;
        return radius * glm::dvec3(std::sin(angle), 0.0, std::cos(angle));
    }
    glm::dvec3 direction(int z, int a) const {
        const double zenith = (z + 0.5) / nz_ * kPi, azimuth = (a + 0.5) / na_ * kPi;
        return {std::sin(zenith) * std::cos(azimuth), std::sin(zenith) * std::sin(azimuth), std::cos(zenith)};
    }

    // Quadrilinear interpolation at any point and direction: the point turned about the sun's
    // axis into the xz plane, the direction with it; the azimuth folded into 0..pi.
    double sample(glm::dvec3 q, glm::dvec3 w) const {
        const double radius = glm::length(q);
        const double turn = std::atan2(q.y, q.x);
        const double c = std::cos(-turn), s = std::sin(-turn);
        const glm::dvec3 v(c * w.x - s * w.y, s * w.x + c * w.y, w.z);
        const double pointAngle = radius > 1e-9 ? std::acos(std::clamp(q.z / radius, -1.0, 1.0)) : 0.0;
        const double zenith = std::acos(std::clamp(v.z, -1.0, 1.0));
        const double azimuth = std::abs(std::atan2(v.y, v.x));
        const double coords[4] = {radius * (nr_ - 1), pointAngle / kPi * np_ - 0.5, zenith / kPi * nz_ - 0.5, azimuth / kPi * na_ - 0.5};
        const int sizes[4] = {nr_, np_, nz_, na_};
        int i0[4];
        double f[4];
        for (int k = 0; k < 4; ++k) {
            const double x = std::clamp(coords[k], 0.0, static_cast<double>(sizes[k] - 1));
            i0[k] = std::min(static_cast<int>(x), sizes[k] - 2 >= 0 ? sizes[k] - 2 : 0);
            f[k] = sizes[k] > 1 ? x - i0[k] : 0.0;
        }
        double sum = 0.0;
        for (int corner = 0; corner < 16; ++corner) {
            double weight = 1.0;
            int idx[4];
            for (int k = 0; k < 4; ++k) {
                const int bit = (corner >> k) & 1;
                idx[k] = std::min(i0[k] + bit, sizes[k] - 1);
                weight *= bit ? f[k] : 1.0 - f[k];
            }
            if (weight > 0.0) sum += weight * at(idx[0], idx[1], idx[2], idx[3]);
        }
        return sum;
    }

    int radii() const { return nr_; }
    int points() const { return np_; }
    int zeniths() const { return nz_; }
    int azimuths() const { return na_; }

private:
    int nr_, np_, nz_, na_;
    std::vector<double> values_;
};

// Light arriving at `end` along `w` from the surface behind it, from the source `source(q, w)`:
// integral of beta e^(-beta t) J dt. The segments carry equal shares of the weight
// beta e^(-beta t) (its integral to the surface, W = 1 - e^(-tau length), in `steps` equal parts),
// J taken at each share's middle: in a sphere of optical radius 14 the light comes from the first
// few metres, where uniform steps would miss it.
template <typename Source>
double transport(double tau, glm::dvec3 end, glm::dvec3 w, int steps, Source&& source) {
    const double length = distanceToSurface(end, -w);
    const double total = 1.0 - std::exp(-tau * length);
    if (!(total > 0.0)) return 0.0;
    double sum = 0.0;
    for (int k = 0; k < steps; ++k) {
        const double t = -std::log(1.0 - total * (k + 0.5) / steps) / tau;
        sum += source(end - w * t, w);
    }
    return sum * total / steps;
}
}  // namespace

double ParticleScatteringParameters::opticalRadius(int layer) const { return std::ldexp(firstOpticalRadius, layer); }

ParticleScatteringParameters ParticleScatteringParameters::sphere(double tau) {
    ParticleScatteringParameters p;
    p.firstOpticalRadius = tau;
    p.opticalRadii = 1;
    return p;
}

std::string ParticleScatteringParameters::describe() const {
    char text[480];
    std::snprintf(text, sizeof(text),
                  "spheres of optical radius %.6g x 2^k, k < %d; Henyey-Greenstein g %.6g; orders 1.. until one adds < %.3g, at most %d; "
                  "surface %d x %d x %d (entry angle, view azimuth, view zenith); field %d x %d x %d x %d (radius, point angle, direction "
                  "zenith, direction azimuth); %d steps",
                  firstOpticalRadius, opticalRadii, asymmetry, convergence, orders, entryAngles, viewAzimuths, viewZeniths, radii,
                  pointAngles, directionZeniths, directionAzimuths, steps);
    return text;
}

double henyeyGreenstein(double cosine, double g) {
    const double denominator = 1.0 + g * g - 2.0 * g * cosine;
    return (1.0 - g * g) / (4.0 * kPi * denominator * std::sqrt(denominator));
}

SurfaceRay scatteringRay(double u0, double u1, double u2) {
    const double entryAngle = u0 * kPi;
    SurfaceRay ray;
    ray.entry = glm::dvec3(std::sin(entryAngle), 0.0, std::cos(entryAngle));
    const glm::dvec3 z = -ray.entry;
    glm::dvec3 x = kSun - glm::dot(kSun, z) * z;
    x = glm::length(x) > 1e-9 ? glm::normalize(x) : glm::dvec3(1.0, 0.0, 0.0);
    const glm::dvec3 y = glm::cross(z, x);
    const double zenith = u2 * 0.5 * kPi, azimuth = (u1 - 0.5) * 2.0 * kPi;
    ray.direction = std::cos(zenith) * z + std::sin(zenith) * (std::cos(azimuth) * x + std::sin(azimuth) * y);
    return ray;
}

SurfaceRay scatteringTexelRay(const ParticleScatteringParameters& p, int entry, int azimuth, int zenith) {
    return scatteringRay((entry + 0.5) / p.entryAngles, (azimuth + 0.5) / p.viewAzimuths, (zenith + 0.5) / p.viewZeniths);
}

double singleScatteringQuadrature(double tau, const SurfaceRay& ray, int steps) {
    // The light leaving at the entry point travels along -direction: it comes from the points
    // along +direction.
    return transport(tau, ray.entry, -ray.direction, steps, [&](glm::dvec3 q, glm::dvec3) { return sunTransmittance(tau, q); });
}

namespace {
// The gather's weights over the full sphere of directions: the stored azimuths and their mirror
// images, each with its solid angle sin(zenith) dzenith dazimuth. The phase function sampled on
// these directions is made exactly conservative by symmetric Sinkhorn scaling: W_ij = s_i s_j
// p_ij w_j with every row summing to 1, so that J is a weighted mean of L (no absorption) and,
// p_ij being symmetric, the gather neither makes nor loses energy (sum_i w_i W_ij = w_j). Rows
// of the stored directions (zenith z, azimuth a < na is full-sphere index z * 2na + a).
std::vector<double> gatherWeights(int nz, int na, double g) {
    const int count = nz * 2 * na;
    std::vector<glm::dvec3> directions(count);
    std::vector<double> solidAngle(count);
    for (int gz = 0; gz < nz; ++gz)
        for (int ge = 0; ge < 2 * na; ++ge) {
            const double zenith = (gz + 0.5) / nz * kPi, azimuth = (ge + 0.5) / (2 * na) * 2.0 * kPi;
            directions[gz * 2 * na + ge] = glm::dvec3(std::sin(zenith) * std::cos(azimuth), std::sin(zenith) * std::sin(azimuth), std::cos(zenith));
            solidAngle[gz * 2 * na + ge] = std::sin(zenith) * (kPi / nz) * (kPi / na);
        }
    std::vector<double> phase(static_cast<size_t>(count) * count), scale(count, 1.0);
    for (int i = 0; i < count; ++i)
        for (int j = 0; j < count; ++j) phase[static_cast<size_t>(i) * count + j] = henyeyGreenstein(glm::dot(directions[i], directions[j]), g);
    for (int iteration = 0; iteration < 200; ++iteration)
        for (int i = 0; i < count; ++i) {
            double row = 0.0;
            for (int j = 0; j < count; ++j) row += phase[static_cast<size_t>(i) * count + j] * scale[j] * solidAngle[j];
            scale[i] = std::sqrt(scale[i] / row);
        }
    std::vector<double> weights(static_cast<size_t>(nz) * na * count);
    for (int z = 0; z < nz; ++z)
        for (int a = 0; a < na; ++a) {
            const int i = z * 2 * na + a;
            double* row = &weights[(static_cast<size_t>(z) * na + a) * count];
            for (int j = 0; j < count; ++j) row[j] = scale[i] * scale[j] * phase[static_cast<size_t>(i) * count + j] * solidAngle[j];
        }
    return weights;
}

// One layer, the sphere of optical radius tauTrue: its single scattering, then its multiple
// scattering order by order until an order adds less than the convergence share; returns the
// last order added.
int computeLayer(const ParticleScatteringParameters& p, double tauTrue, const std::vector<SurfaceRay>& rays, const std::vector<double>& weights,
                 float* single, float* peak, float* multiple) {
    // The delta-M scaled medium (Wiscombe 1977): the phase function's forward peak, narrower than
    // the field's directions can hold, counts as unscattered light; the medium keeps the rest.
    // With f = g^2: extinction (1 - f) beta, asymmetry (g - f) / (1 - f).
    const double f = p.asymmetry * p.asymmetry;
    const double tau = tauTrue * (1.0 - f), g = (p.asymmetry - f) / (1.0 - f);
    // Single scattering in the true sphere (the renderer applies the true phase function); and
    // what the scaled sphere's first order adds to it, the light scattered into the forward peak
    // on its way in or out and then once more (the renderer applies the scaled phase function):
    // the first order of the scaled sphere, whose scattering coefficient is (1 - f) beta, less
    // the true single scattering's share of it.
    const size_t texels = rays.size();
    for (size_t k = 0; k < texels; ++k) {
        const double once = singleScatteringQuadrature(tauTrue, rays[k], kSingleStepsPerStep * p.steps);
        const double scaled = singleScatteringQuadrature(tau, rays[k], kSingleStepsPerStep * p.steps);
        single[k] = static_cast<float>(once);
        peak[k] = static_cast<float>(std::max(scaled - (1.0 - f) * once, 0.0));
    }
    if (p.orders < 2) return 1;

    // Order 1 inside: the sun's light scattered once, J_1 = T_sun p(-sun . w).
    Field radiance(p), source(p);
    const auto firstSource = [&](glm::dvec3 q, glm::dvec3 w) { return sunTransmittance(tau, q) * henyeyGreenstein(glm::dot(-kSun, w), g); };
    for (int r = 0; r < radiance.radii(); ++r)
        for (int pa = 0; pa < radiance.points(); ++pa)
            for (int z = 0; z < radiance.zeniths(); ++z)
                for (int a = 0; a < radiance.azimuths(); ++a)
                    radiance.at(r, pa, z, a) = transport(tau, radiance.point(r, pa), radiance.direction(z, a), p.steps, firstSource);

    const int nz = radiance.zeniths(), na = radiance.azimuths();
    double total = 0.0;
    int order = 2;
    for (;; ++order) {
        // J_n from L_{n-1}, at every point of the field.
        for (int r = 0; r < radiance.radii(); ++r)
            for (int pa = 0; pa < radiance.points(); ++pa)
                for (int z = 0; z < nz; ++z)
                    for (int a = 0; a < na; ++a) {
                        const double* row = &weights[(static_cast<size_t>(z) * na + a) * nz * 2 * na];
                        double j = 0.0;
                        for (int gz = 0; gz < nz; ++gz)
                            for (int ge = 0; ge < 2 * na; ++ge) j += row[gz * 2 * na + ge] * radiance.at(r, pa, gz, ge < na ? ge : 2 * na - 1 - ge);
                        source.at(r, pa, z, a) = j;
                    }
        const auto orderSource = [&](glm::dvec3 q, glm::dvec3 w) { return source.sample(q, w); };
        // The radiance this order adds leaving the surface...
        double added = 0.0;
        for (size_t k = 0; k < texels; ++k) {
            const double light = transport(tau, rays[k].entry, -rays[k].direction, p.steps, orderSource);
            multiple[k] += static_cast<float>(light);
            added += light;
        }
        total += added;
        if (order >= p.orders || !(added > p.convergence * total)) break;
        // ...and inside, for the next order.
        for (int r = 0; r < radiance.radii(); ++r)
            for (int pa = 0; pa < radiance.points(); ++pa)
                for (int z = 0; z < nz; ++z)
                    for (int a = 0; a < na; ++a)
                        radiance.at(r, pa, z, a) = transport(tau, radiance.point(r, pa), radiance.direction(z, a), p.steps, orderSource);
    }
    return order;
}
}  // namespace

ParticleScatteringTable computeParticleScattering(const ParticleScatteringParameters& p, const std::function<void(double)>& progress, int onlyLayer) {
    ParticleScatteringTable table;
    table.parameters = p;
    const size_t texels = static_cast<size_t>(p.entryAngles) * p.viewAzimuths * p.viewZeniths;
    table.single.assign(texels * p.opticalRadii, 0.0f);
    table.peak.assign(texels * p.opticalRadii, 0.0f);
    table.multiple.assign(texels * p.opticalRadii, 0.0f);
    table.orders.assign(p.opticalRadii, 0);
    std::vector<SurfaceRay> rays(texels);
    for (int z = 0; z < p.viewZeniths; ++z)
        for (int a = 0; a < p.viewAzimuths; ++a)
            for (int e = 0; e < p.entryAngles; ++e) rays[table.index(e, a, z)] = scatteringTexelRay(p, e, a, z);
    const double f = p.asymmetry * p.asymmetry;
    const std::vector<double> weights = gatherWeights(p.directionZeniths, p.directionAzimuths, (p.asymmetry - f) / (1.0 - f));
    for (int layer = 0; layer < p.opticalRadii; ++layer) {
        if (onlyLayer >= 0 && layer != onlyLayer) continue;
        const size_t first = table.index(0, 0, 0, layer);
        table.orders[layer] = computeLayer(p, p.opticalRadius(layer), rays, weights, &table.single[first], &table.peak[first], &table.multiple[first]);
        if (progress) progress(static_cast<double>(layer + 1) / p.opticalRadii);
    }
    return table;
}

namespace {
constexpr int kFileFormat = 3;  // raise when the file's layout changes
}  // namespace

std::string particleScatteringKey(const ParticleScatteringParameters& p) {
    return tableKey("cloud particle scattering: " + p.describe() + "; format=" + std::to_string(kFileFormat));
}

void writeParticleScattering(const std::filesystem::path& path, const ParticleScatteringTable& table) {
    const ParticleScatteringParameters& p = table.parameters;
    FloatRgbaImage image{p.entryAngles * p.viewZeniths, p.viewAzimuths * p.opticalRadii, {}};
    image.rgba.assign(static_cast<size_t>(image.width) * image.height * 4, 0.0f);
    for (int layer = 0; layer < p.opticalRadii; ++layer)
        for (int z = 0; z < p.viewZeniths; ++z)
            for (int a = 0; a < p.viewAzimuths; ++a)
                for (int e = 0; e < p.entryAngles; ++e) {
                    const size_t pixel = ((static_cast<size_t>(layer) * p.viewAzimuths + a) * image.width + z * p.entryAngles + e) * 4;
                    image.rgba[pixel] = table.single[table.index(e, a, z, layer)];
                    image.rgba[pixel + 1] = table.multiple[table.index(e, a, z, layer)];
                    image.rgba[pixel + 2] = table.peak[table.index(e, a, z, layer)];
                }
    std::string orders;
    for (int layer = 0; layer < p.opticalRadii; ++layer) orders += (layer ? ", " : "") + std::to_string(table.orders.empty() ? 0 : table.orders[layer]);
    ExrAttributes a;
    a["firmament.lut.key"] = particleScatteringKey(p);
    a["firmament.lut.formatVersion"] = kFileFormat;
    a["firmament.lut.name"] = std::string(
        "cloud particle scattering (Yusov 2014): radiance leaving homogeneous spheres of several optical radii lit by the sun, per "
        "unit sun irradiance (1/sr). "
        "R: single scattering without its phase function; G: multiple scattering, orders 2..N in the delta-M scaled medium; B: the scaled "
        "medium's first order beyond the share of it that R is (the light scattered into the forward peak and once more), without its "
        "phase function");
    a["firmament.lut.dimensions"] = p.describe();
    a["firmament.lut.parameterization"] = std::string(
        "sun along +z; entry point s at angle theta_s from it: u0 = theta_s / pi; view direction d into the sphere, in the frame Z = -s, "
        "X = the sun's direction across Z, Y = Z x X: u1 = atan2(d.Y, d.X) / 2pi + 1/2, u2 = acos(d.Z) / (pi/2). Texel centres.");
    a["firmament.lut.layout"] = std::string(
        "x: entry angle within a tile, one tile per view zenith side by side; y: view azimuth within a row of tiles, one row per optical "
        "radius (the first at the top)");
    a["firmament.lut.orders"] = "the last order added, by optical radius: " + orders;
    a["firmament.lut.generator"] = std::string("firmament --generate-cloud-scattering <file> (tools/generate-cloud-scattering)");
    writeExr(path, image, a);
}

ParticleScatteringTable readParticleScattering(const std::filesystem::path& path, const ParticleScatteringParameters& expected) {
    std::error_code ec;
    if (!std::filesystem::exists(path, ec)) throw Error(path.string() + ": the cloud particle's scattering table is missing (tools/generate-cloud-scattering makes it)");
    const FloatExrFile file = readFloatExr(path);
    const std::string key = particleScatteringKey(expected);
    if (const std::string why = checkTableHeader(file.attributes, key, expected.entryAngles * expected.viewZeniths,
                                                 expected.viewAzimuths * expected.opticalRadii,
                                                 file.image.width, file.image.height);
        !why.empty())
        throw Error(path.string() + ": " + why + "; run tools/generate-cloud-scattering to make it for this program");
    ParticleScatteringTable table;
    table.parameters = expected;
    const size_t texels = static_cast<size_t>(expected.entryAngles) * expected.viewAzimuths * expected.viewZeniths * expected.opticalRadii;
    table.single.resize(texels);
    table.peak.resize(texels);
    table.multiple.resize(texels);
    for (int layer = 0; layer < expected.opticalRadii; ++layer)
        for (int z = 0; z < expected.viewZeniths; ++z)
            for (int a = 0; a < expected.viewAzimuths; ++a)
                for (int e = 0; e < expected.entryAngles; ++e) {
                    const size_t pixel = ((static_cast<size_t>(layer) * expected.viewAzimuths + a) * file.image.width + z * expected.entryAngles + e) * 4;
                    table.single[table.index(e, a, z, layer)] = file.image.rgba[pixel];
                    table.multiple[table.index(e, a, z, layer)] = file.image.rgba[pixel + 1];
                    table.peak[table.index(e, a, z, layer)] = file.image.rgba[pixel + 2];
                }
    return table;
}

}  // namespace firmament
