#include "terrain/TerrainSurface.h"

#include "core/IntegerHash.h"

#include <algorithm>
#include <cmath>
#include <cstdint>

namespace firmament {

namespace {

// The mask's offset: puts the origin on a range (found by a search over the mask).
constexpr double kRangeOffsetX = 85000.0, kRangeOffsetZ = -390000.0;

// A lattice value in [-1, 1].
double latticeValue(int i, int j, int octave) {
    const std::uint32_t h = hash32(static_cast<std::uint32_t>(i) ^ hash32(static_cast<std::uint32_t>(j) ^ hash32(static_cast<std::uint32_t>(octave) + 0x9e3779b9u)));
    return static_cast<double>(h & 0xffffffu) / 16777215.0 * 2.0 - 1.0;
}

double fade(double t) { return t * t * t * (t * (t * 6.0 - 15.0) + 10.0); }

double valueNoise(double x, double z, int octave) {
    const double fx = std::floor(x), fz = std::floor(z);
    const int i = static_cast<int>(fx), j = static_cast<int>(fz);
    const double u = fade(x - fx), v = fade(z - fz);
    const double top = latticeValue(i, j, octave) * (1.0 - u) + latticeValue(i + 1, j, octave) * u;
    const double bottom = latticeValue(i, j + 1, octave) * (1.0 - u) + latticeValue(i + 1, j + 1, octave) * u;
    return top * (1.0 - v) + bottom * v;
}

double smoothstep(double e0, double e1, double x) {
    const double t = std::clamp((x - e0) / (e1 - e0), 0.0, 1.0);
    return t * t * (3.0 - 2.0 * t);
}

}  // namespace

double rangeMask(double x, double z) {
    x += kRangeOffsetX;
    z += kRangeOffsetZ;
    // Warp by up to 30 km, so that the bands wind instead of following the lattice.
    const double warpX = 30000.0 * valueNoise(x / 70000.0, z / 70000.0, 20);
    const double warpZ = 30000.0 * valueNoise(x / 70000.0, z / 70000.0, 21);
    const double qx = x + warpX, qz = z + warpZ;
    // The two noises on lattices turned by +-37 degrees (a 3-4-5 triangle, exact in float) from
    // the warp's, so that no lattice's axes show.
    const double ax = 0.8 * qx - 0.6 * qz, az = 0.6 * qx + 0.8 * qz;
    const double bx = 0.8 * qx + 0.6 * qz, bz = -0.6 * qx + 0.8 * qz;
    // 1 where the band's noise crosses zero (|n| made smooth there), falling off to either side.
    const double n = valueNoise(ax / 160000.0, az / 160000.0, 22) + 0.5 * valueNoise(bx / 67000.0, bz / 67000.0, 24);
    const double band = 1.0 - std::sqrt(n * n + 0.04);
    const double massifs = 0.5 + 0.5 * valueNoise(bx / 45000.0, bz / 45000.0, 23);
    const double ranges = smoothstep(0.55, 0.8, band * (0.8 + 0.4 * massifs));
    return kPlainsRelief + (1.0 - kPlainsRelief) * ranges;
}

double detailHeight(double x, double z, double spacing) {
    double sum = 0.0, wavelength = kDetailLongestWavelength;
    for (int o = 0; o < kDetailOctaves; ++o, wavelength *= 0.5) {
        const double weight = std::clamp(wavelength / (2.0 * spacing) - 1.0, 0.0, 1.0);
        if (weight > 0.0) sum += weight * kDetailAmplitude * wavelength * valueNoise(x / wavelength, z / wavelength, o);
    }
    return sum;
}

int heightMipFor(double spacing, const HeightField& field) {
    int mip = 0;
    while (mip + 1 < field.mipCount() && field.spacing() * static_cast<double>(2 << mip) <= spacing) ++mip;
    return mip;
}

double surfaceHeight(const HeightField& field, double x, double z, double spacing) {
    return rangeMask(x, z) * field.sample(x, z, heightMipFor(spacing, field)) + detailHeight(x, z, spacing);
}

double earthDrop(double x, double z, double earthRadius) {
    const double r2 = x * x + z * z;
    return r2 / (earthRadius + std::sqrt(std::max(earthRadius * earthRadius - r2, 0.0)));
}

}  // namespace firmament
