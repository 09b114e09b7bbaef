#include "terrain/TerrainSurface.h"

#include "terrain/IntegerHash.h"

#include <algorithm>
#include <cmath>
#include <cstdint>

namespace firmament {

namespace {

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

}  // namespace

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
    return field.sample(x, z, heightMipFor(spacing, field)) + detailHeight(x, z, spacing);
}

double earthDrop(double x, double z, double earthRadius) {
    const double r2 = x * x + z * z;
    return r2 / (earthRadius + std::sqrt(std::max(earthRadius * earthRadius - r2, 0.0)));
}

}  // namespace firmament
