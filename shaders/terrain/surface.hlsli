#ifndef FIRMAMENT_TERRAIN_SURFACE_HLSLI
#define FIRMAMENT_TERRAIN_SURFACE_HLSLI
// The terrain's surface (docs/terrain.md): the height field, bilinear at the mip a grid's vertex
// spacing calls for and scaled by where the mountain ranges stand, plus metre-scale detail noise,
// on the Earth's sphere. The CPU twin is src/terrain/TerrainSurface.cpp; tests/gpu/TerrainTest.cpp
// holds the two together.
#include "terrain/terrain_structures.hlsli"

// Wellons' lowbias32 integer hash, as the CPU twin.
uint hash32(uint x) {
    x ^= x >> 16;
    x *= 0x7feb352du;
    x ^= x >> 15;
    x *= 0x846ca68bu;
    x ^= x >> 16;
    return x;
}

float latticeValue(int i, int j, uint octave) {
    uint h = hash32(asuint(i) ^ hash32(asuint(j) ^ hash32(octave + 0x9e3779b9u)));
    return float(h & 0xffffffu) / 16777215.0 * 2.0 - 1.0;
}

float quinticFade(float t) { return t * t * t * (t * (t * 6.0 - 15.0) + 10.0); }

float valueNoise(float2 p, uint octave) {
    float2 f = floor(p);
    int i = (int)f.x, j = (int)f.y;
    float2 w = float2(quinticFade(p.x - f.x), quinticFade(p.y - f.y));
    float top = lerp(latticeValue(i, j, octave), latticeValue(i + 1, j, octave), w.x);
    float bottom = lerp(latticeValue(i, j + 1, octave), latticeValue(i + 1, j + 1, octave), w.x);
    return lerp(top, bottom, w.y);
}

static const uint kDetailOctaves = 5;
static const float kDetailLongestWavelength = 64.0;
static const float kDetailAmplitude = 0.06;  // of the wavelength

// Detail octaves a grid of vertex spacing `spacing` resolves (weight saturate(lambda / 2s - 1)).
float detailHeight(float2 p, float spacing) {
    float sum = 0.0;
    float wavelength = kDetailLongestWavelength;
    [unroll] for (uint o = 0; o < kDetailOctaves; ++o) {
        float weight = saturate(wavelength / (2.0 * spacing) - 1.0);
        sum += weight * kDetailAmplitude * wavelength * valueNoise(p / wavelength, o);
        wavelength *= 0.5;
    }
    return sum;
}

// Where mountain ranges stand: the CPU twin's rangeMask (TerrainSurface.h), a mask in
// [kPlainsRelief, 1] over lattices of 45 to 160 km that do not repeat with the height field's
// tile: warped bands where a noise crosses zero, broken into massifs.
static const float kPlainsRelief = 0.1;
static const float2 kRangeOffset = float2(85000.0, -390000.0);

float rangeMask(float2 p) {
    p += kRangeOffset;
    float2 q = p + 30000.0 * float2(valueNoise(p / 70000.0, 20), valueNoise(p / 70000.0, 21));
    float2 a = float2(0.8 * q.x - 0.6 * q.y, 0.6 * q.x + 0.8 * q.y);   // lattices turned by +-37 degrees
    float2 b = float2(0.8 * q.x + 0.6 * q.y, -0.6 * q.x + 0.8 * q.y);
    float n = valueNoise(a / 160000.0, 22) + 0.5 * valueNoise(b / 67000.0, 24);
    float band = 1.0 - sqrt(n * n + 0.04);
    float massifs = 0.5 + 0.5 * valueNoise(b / 45000.0, 23);
    return kPlainsRelief + (1.0 - kPlainsRelief) * smoothstep(0.55, 0.8, band * (0.8 + 0.4 * massifs));
}

// The mask's gradient by central differences over 100 m (its features span tens of km).
float2 rangeMaskGradient(float2 p) {
    const float d = 100.0;
    return float2(rangeMask(p + float2(d, 0.0)) - rangeMask(p - float2(d, 0.0)),
                  rangeMask(p + float2(0.0, d)) - rangeMask(p - float2(0.0, d))) / (2.0 * d);
}

// Bilinear between texel centres of mip `mip`, wrapping: loads, not the sampler, so that the
// weights are full float and the CPU twin can match them.
float heightFieldAt(TerrainConstants t, Texture2D<float> heights, float2 p, uint mip) {
    float texelsPerSide = t.field.y / float(1u << mip);
    float2 texel = (p / t.field.x + 0.5) / float(1u << mip) - 0.5;
    float2 f = floor(texel);
    float2 w = texel - f;
    int mask = (int)texelsPerSide - 1;  // a power of two: & wraps negatives too
    int i = (int)f.x, j = (int)f.y;
    float h00 = heights.Load(int3(i & mask, j & mask, mip));
    float h10 = heights.Load(int3((i + 1) & mask, j & mask, mip));
    float h01 = heights.Load(int3(i & mask, (j + 1) & mask, mip));
    float h11 = heights.Load(int3((i + 1) & mask, (j + 1) & mask, mip));
    return lerp(lerp(h00, h10, w.x), lerp(h01, h11, w.x), w.y);
}

// Height above the sea-level sphere of the surface a grid of spacing `spacing` draws: the range
// mask times the height field, plus the detail.
float surfaceHeight(TerrainConstants t, Texture2D<float> heights, float2 p, float spacing, uint mip) {
    return rangeMask(p) * heightFieldAt(t, heights, p, mip) + detailHeight(p, spacing);
}

// How far the Earth's sphere (centre (0, -R, 0)) lies below the plane y = 0 at p:
// r^2 / (R + sqrt(R^2 - r^2)), free of the cancellation of sqrt(R^2 - r^2) - R.
float earthDrop(float2 p, float earthRadius) {
    float r2 = dot(p, p);
    return r2 / (earthRadius + sqrt(max(earthRadius * earthRadius - r2, 0.0)));
}

// World y of the surface point above p.
float surfaceY(TerrainConstants t, Texture2D<float> heights, float2 p, float spacing, uint mip) {
    return surfaceHeight(t, heights, p, spacing, mip) - earthDrop(p, t.field.w);
}

#endif
