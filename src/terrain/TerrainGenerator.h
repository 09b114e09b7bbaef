#pragma once
// The terrain's height field: a deterministic, tileable fractal (docs/terrain.md). Ridged
// multifractal noise (Musgrave's, in "Texturing and Modeling: A Procedural Approach") for the
// mountains, over a few octaves of plain fractal noise for hills and valleys, with a low-frequency
// mask that leaves plains between the ranges. Every noise lattice wraps with the tile, so the
// field repeats seamlessly and the terrain extends without end.
//
// Determinism: integer hashing picks the gradients (no trigonometry, no library random
// numbers), and the arithmetic is double precision IEEE 754, so the same parameters give
// bit-identical heights on every x86-64 compiler and run (tests/unit/TerrainGeneratorTest.cpp).
#include <cstdint>
#include <string>
#include <vector>

namespace firmament {

struct TerrainGeneratorParameters {
    std::uint32_t seed = 2013;   // Yusov's year; any value gives another terrain
    int size = 2048;             // samples along each side (a power of two)
    double spacing = 16.0;       // metres between samples: 2048 x 16 m = 32.8 km to a tile
    int baseCells = 8;           // lattice cells across the tile in the first octave (4.1 km features)
    int ridgeOctaves = 8;        // wavelengths from 4.1 km down to 32 m (two samples)
    double mountainHeight = 3200.0;  // metres: the ridges' full amplitude
    double hillHeight = 350.0;       // metres: the rolling fractal's amplitude

    std::string describe() const;  // every parameter, as text (the cache key is made from it)
};

// Heights in metres, row-major (row = z index, column = x index), size x size, sample (i, j)
// at x = i * spacing, z = j * spacing. Never negative: the lowest valleys sit at sea level.
std::vector<float> generateHeights(const TerrainGeneratorParameters& parameters);

// Periodic gradient noise (Perlin's, with quintic fade) of period `period` lattice cells, at
// lattice coordinates (x, z): about [-1, 1], zero at lattice points. Exposed for its tests.
double gradientNoise(double x, double z, int period, std::uint32_t seed);

}  // namespace firmament
