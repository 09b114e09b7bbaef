#ifndef FIRMAMENT_VOLUME_BLENDING_HLSLI
#define FIRMAMENT_VOLUME_BLENDING_HLSLI
// Volume-aware blending of cloud particles (Yusov 2014, "Volume-aware blending"; docs/clouds.md,
// "Blending"). The CPU twin is src/reference/VolumeBlendingTwin.cpp, which the tests hold against the
// emission-absorption integral.
//
// A fragment is the stretch [front, back] of the view ray inside a particle, with a uniform
// extinction and the radiance the particle sends toward the camera (not premultiplied).

struct ParticleFragment {
    float3 colour;
    float extinction;  // rho * beta (1/m)
    float front;       // distances from the camera (m)
    float back;
};

// Light over the scene: `light` premultiplied, the scene seen through `transmittance`.
struct BlendedLight {
    float3 light;
    float transmittance;
};

BlendedLight noLight() {
    BlendedLight b;
    b.light = 0.0;
    b.transmittance = 1.0;
    return b;
}

float fragmentTransmittance(ParticleFragment f) { return exp(-f.extinction * max(f.back - f.front, 0.0)); }

// f over behind: C = c (1 - T) + T C_behind.
BlendedLight blendOver(ParticleFragment f, BlendedLight behind) {
    float t = fragmentTransmittance(f);
    BlendedLight b;
    b.light = f.colour * (1.0 - t) + t * behind.light;
    b.transmittance = t * behind.transmittance;
    return b;
}

// Two overlapping fragments as one over their union (Yusov 2014): the front and back stretches
// each of the particle that owns it, the intersection with the summed extinction and the
// extinction-weighted colour;
//   T = T_front T_isec T_back, c = (C_front + C_isec T_front + C_back T_front T_isec) / (1 - T),
// the merged extinction the one that keeps the total optical depth.
ParticleFragment mergeOverlapping(ParticleFragment a, ParticleFragment b) {
    // The fragment that starts first owns the front stretch, the one that ends last the back.
    // (Selected field by field: vkd3d-compiler 2.1 cannot select whole structs.)
    bool aFirst = a.front <= b.front, aLast = a.back >= b.back;
    float3 firstColour = aFirst ? a.colour : b.colour, lastColour = aLast ? a.colour : b.colour;
    float firstExtinction = aFirst ? a.extinction : b.extinction, lastExtinction = aLast ? a.extinction : b.extinction;
    float lo = min(a.front, b.front), hi = max(a.back, b.back);
    float isecStart = max(a.front, b.front);
    float isecEnd = max(min(a.back, b.back), isecStart);
    float tauFront = firstExtinction * (isecStart - lo);
    float sumExtinction = a.extinction + b.extinction;
    float tauIsec = sumExtinction * (isecEnd - isecStart);
    float tauBack = lastExtinction * (hi - isecEnd);
    float3 isecColour = sumExtinction > 0.0 ? (a.colour * a.extinction + b.colour * b.extinction) / sumExtinction : 0.5 * (a.colour + b.colour);
    float tFront = exp(-tauFront), tIsec = exp(-tauIsec), tBack = exp(-tauBack);
    float tau = tauFront + tauIsec + tauBack;
    float opacity = 1.0 - tFront * tIsec * tBack;

    ParticleFragment merged;
    merged.front = lo;
    merged.back = hi;
    merged.extinction = hi > lo ? tau / (hi - lo) : 0.0;
    if (opacity > 1e-6)
        merged.colour = (firstColour * (1.0 - tFront) + isecColour * (1.0 - tIsec) * tFront + lastColour * (1.0 - tBack) * tFront * tIsec) / opacity;
    else if (tau > 0.0)
        merged.colour = (firstColour * tauFront + isecColour * tauIsec + lastColour * tauBack) / tau;
    else
        merged.colour = 0.5 * (a.colour + b.colour);
    return merged;
}

// One pixel's blending as fragments arrive back to front.
struct VolumeBlend {
    BlendedLight behind;
    ParticleFragment current;
    bool hasCurrent;
};

VolumeBlend emptyVolumeBlend() {
    VolumeBlend v;
    v.behind = noLight();
    v.current = (ParticleFragment)0;
    v.hasCurrent = false;
    return v;
}

// A fragment in front of the stored one pushes it behind; an overlapping one merges with it;
// one wholly behind it goes behind it.
void addFragment(inout VolumeBlend v, ParticleFragment f) {
    if (!v.hasCurrent) {
        v.current = f;
        v.hasCurrent = true;
    } else if (f.back <= v.current.front) {
        v.behind = blendOver(v.current, v.behind);
        v.current = f;
    } else if (f.front >= v.current.back) {
        v.behind = blendOver(f, v.behind);
    } else {
        v.current = mergeOverlapping(v.current, f);
    }
}

BlendedLight resolveVolumeBlend(VolumeBlend v) {
    if (v.hasCurrent) return blendOver(v.current, v.behind);
    return v.behind;
}

#endif
