#include "terrain/TerrainGenerator.h"

#include "core/IntegerHash.h"

#include <algorithm>
#include <cmath>
#include <sstream>
#include <thread>

namespace firmament {

namespace {

std::uint32_t latticeHash(int x, int z, std::uint32_t seed) {
    return hash32(static_cast<std::uint32_t>(x) ^ hash32(static_cast<std::uint32_t>(z) ^ hash32(seed)));
}

// Eight gradient directions, picked by the hash: the axes and the diagonals.
constexpr double kDiagonal = 0.70710678118654752440;
constexpr double kGradients[8][2] = {{1, 0}, {-1, 0}, {0, 1}, {0, -1},
                                     {kDiagonal, kDiagonal}, {-kDiagonal, kDiagonal}, {kDiagonal, -kDiagonal}, {-kDiagonal, -kDiagonal}};

double fade(double t) { return t * t * t * (t * (t * 6.0 - 15.0) + 10.0); }  // Perlin's quintic: C2 at lattice points

int wrap(int i, int period) { return ((i % period) + period) % period; }

double cornerContribution(int ix, int iz, double dx, double dz, int period, std::uint32_t seed) {
    const double* g = kGradients[latticeHash(wrap(ix, period), wrap(iz, period), seed) & 7u];
    return g[0] * dx + g[1] * dz;
}

double lerp(double a, double b, double t) { return a + (b - a) * t; }

// Sum of `octaves` octaves of gradient noise, each twice the frequency and half the amplitude
// of the one before, over `cells` lattice cells across the tile at (u, v) in tile units.
double fractalNoise(double u, double v, int cells, int octaves, std::uint32_t seed) {
    double sum = 0.0, amplitude = 1.0;
    for (int o = 0; o < octaves; ++o, cells *= 2, amplitude *= 0.5)
        sum += amplitude * gradientNoise(u * cells, v * cells, cells, seed + static_cast<std::uint32_t>(o) * 101u);
    return sum;
}

// Musgrave's ridged multifractal: each octave's ridge (1 - |n|)^2 is weighted by the octave
// before, so fine ridges grow on the crests of the coarse ones and valleys stay smooth.
double ridgedMultifractal(double u, double v, int cells, int octaves, std::uint32_t seed) {
    constexpr double kOffset = 1.0, kGain = 2.0;
    double sum = 0.0, amplitude = 1.0, weight = 1.0;
    for (int o = 0; o < octaves; ++o, cells *= 2, amplitude *= 0.5) {
        double signal = kOffset - std::abs(gradientNoise(u * cells, v * cells, cells, seed + 7919u * static_cast<std::uint32_t>(o + 1)));
        signal *= signal * weight;
        weight = std::clamp(signal * kGain, 0.0, 1.0);
        sum += signal * amplitude;
    }
    return sum;
}

// One sample's height before the lowest valley is moved to sea level. Mountains stand all over
// the tile: where ranges rise and where plains lie between them is decided by a mask that does
// not repeat with the tile (rangeMask in TerrainSurface.h), so the tile's repetition never shows
// as a lattice of ranges.
double rawHeight(const TerrainGeneratorParameters& p, double u, double v) {
    // Domain warp: bends the ridges away from the lattice's axes. Its displacement (500 m) stays
    // well below its wavelength (4.1 km): a stronger warp shears the ridges into parallel streaks,
    // which from 10 km up read as the grain of wood on every slope.
    const double warpU = 0.015 * fractalNoise(u, v, p.baseCells, 2, p.seed ^ 0xa5a5u);
    const double warpV = 0.015 * fractalNoise(u, v, p.baseCells, 2, p.seed ^ 0x5a5au);
    const double wu = u + warpU, wv = v + warpV;
    const double hills = 0.5 + 0.5 * fractalNoise(wu, wv, p.baseCells / 2, 5, p.seed ^ 0x4321u);
    const double ridges = ridgedMultifractal(wu, wv, p.baseCells, p.ridgeOctaves, p.seed);
    const double ridge = ridges / 2.0;  // the octaves' amplitudes sum to about 2
    return p.hillHeight * hills + p.mountainHeight * ridge * ridge;
}

}  // namespace

double gradientNoise(double x, double z, int period, std::uint32_t seed) {
    const double fx = std::floor(x), fz = std::floor(z);
    const int ix = static_cast<int>(fx), iz = static_cast<int>(fz);
    const double dx = x - fx, dz = z - fz;
    const double n00 = cornerContribution(ix, iz, dx, dz, period, seed);
    const double n10 = cornerContribution(ix + 1, iz, dx - 1.0, dz, period, seed);
    const double n01 = cornerContribution(ix, iz + 1, dx, dz - 1.0, period, seed);
    const double n11 = cornerContribution(ix + 1, iz + 1, dx - 1.0, dz - 1.0, period, seed);
    const double u = fade(dx), v = fade(dz);
    return std::sqrt(2.0) * lerp(lerp(n00, n10, u), lerp(n01, n11, u), v);  // the diagonal's peak scaled to about 1
}

std::string TerrainGeneratorParameters::describe() const {
    std::ostringstream out;
    out.precision(17);
    out << "terrain generator 3: seed " << seed << ", size " << size << ", spacing " << spacing << " m, base cells " << baseCells
        << ", ridge octaves " << ridgeOctaves << ", mountains " << mountainHeight << " m, hills " << hillHeight << " m";
    return out.str();
}

std::vector<float> generateHeights(const TerrainGeneratorParameters& p) {
    const size_t n = static_cast<size_t>(p.size);
    std::vector<double> heights(n * n);
    // Rows are independent: split them over the cores (the result does not depend on how).
    const unsigned workers = std::max(1u, std::thread::hardware_concurrency());
    std::vector<std::thread> threads;
    for (unsigned w = 0; w < workers; ++w) {
        threads.emplace_back([&, w] {
            for (size_t j = w; j < n; j += workers)
                for (size_t i = 0; i < n; ++i)
                    heights[j * n + i] = rawHeight(p, static_cast<double>(i) / static_cast<double>(n), static_cast<double>(j) / static_cast<double>(n));
        });
    }
    for (auto& t : threads) t.join();
    const double lowest = *std::min_element(heights.begin(), heights.end());
    std::vector<float> out(n * n);
    for (size_t k = 0; k < out.size(); ++k) out[k] = static_cast<float>(heights[k] - lowest);
    return out;
}

}  // namespace firmament
