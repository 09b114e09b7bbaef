#ifndef FIRMAMENT_HASH_HLSLI
#define FIRMAMENT_HASH_HLSLI
// Wellons' lowbias32 integer hash (src/core/IntegerHash.h, the CPU twin): every input bit
// changes about half the output bits. The clouds' noises and particles pick their values with it.
uint hash32(uint x) {
    x ^= x >> 16;
    x *= 0x7feb352du;
    x ^= x >> 15;
    x *= 0x846ca68bu;
    x ^= x >> 16;
    return x;
}

// Uniform in [0, 1) from 24 bits of a hash.
float unitFromHash(uint h) { return float(h >> 8) * (1.0 / 16777216.0); }

#endif
