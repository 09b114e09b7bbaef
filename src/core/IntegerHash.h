#pragma once
// Chris Wellons' "lowbias32" integer hash: every input bit changes about half the output bits.
// The terrain's noises and the clouds' field pick their lattice values with it, on the CPU and
// (the same operations on uint) in shaders/terrain/surface.hlsli and shaders/common/hash.hlsli.
#include <cstdint>

namespace firmament {

inline std::uint32_t hash32(std::uint32_t x) {
    x ^= x >> 16;
    x *= 0x7feb352du;
    x ^= x >> 15;
    x *= 0x846ca68bu;
    x ^= x >> 16;
    return x;
}

// Uniform in [0, 1) from the top 24 bits of a hash.
inline float unitFromHash(std::uint32_t h) { return static_cast<float>(h >> 8) * (1.0f / 16777216.0f); }

}  // namespace firmament
