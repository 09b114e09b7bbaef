// The cloud density map (docs/clouds.md, "Cloudiness"): fractal value noise that tiles, from 4
// lattice cells per side to a quarter of the map's resolution, each octave half the amplitude
// of the one before, stretched about 0.5 to fill [0, 1]. The CPU twin is cloudDensityTexel()
// (src/clouds/CloudField.cpp).
#include "clouds/cloud_field.hlsli"

RWTexture2D<float> mapOut : register(u0);

static const float kDensityContrast = 2.5;

float latticeValue(uint x, uint y, uint octave) { return unitFromHash(hash32(x ^ hash32(y ^ hash32(octave + 0x9e3779b9u)))); }

// Perlin's quintic fade: the interpolation weight, flat at the lattice points.
float fade(float t) { return t * t * t * (t * (t * 6.0 - 15.0) + 10.0); }

float densityTexel(uint resolution, uint2 texel) {
    int octaves = max(int(firstbithigh(resolution)) - 3, 1);
    float sum = 0.0, total = 0.0, amplitude = 1.0;
    for (int o = 0; o < octaves; ++o) {
        uint lattice = 4u << o;
        float2 p = (float2(texel) + 0.5) * float(lattice) / float(resolution);
        float2 f = floor(p);
        float tx = fade(p.x - f.x), ty = fade(p.y - f.y);
        uint mask = lattice - 1u;
        uint2 a = uint2(f) & mask;
        uint2 b = (a + 1u) & mask;
        float v00 = latticeValue(a.x, a.y, uint(o)), v10 = latticeValue(b.x, a.y, uint(o));
        float v01 = latticeValue(a.x, b.y, uint(o)), v11 = latticeValue(b.x, b.y, uint(o));
        float bottom = v00 + tx * (v10 - v00);
        float top = v01 + tx * (v11 - v01);
        sum += amplitude * (bottom + ty * (top - bottom));
        total += amplitude;
        amplitude *= 0.5;
    }
    return saturate(0.5 + (sum / total - 0.5) * kDensityContrast);
}

[numthreads(8, 8, 1)]
void main(uint3 id : SV_DispatchThreadID) {
    uint resolution = uint(field.coverage.w);
    if (id.x >= resolution || id.y >= resolution) return;
    mapOut[id.xy] = densityTexel(resolution, id.xy);
}
