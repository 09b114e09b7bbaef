#pragma once
// Chris Wellons' "lowbias32" integer hash: every input bit changes about half the output bits.
// The terrain's noises pick their lattice values with it, on the CPU and (the same operations on
// uint) in shaders/terrain/surface.hlsli.
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

}  // namespace firmament
