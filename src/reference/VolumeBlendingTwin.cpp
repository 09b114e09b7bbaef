#include "reference/VolumeBlendingTwin.h"

#include <algorithm>
#include <cmath>

namespace firmament {

namespace {
// Below this 1 - T the merged colour is the optical-depth-weighted mean, the formula's limit.
constexpr float kThinLimit = 1e-6f;
}  // namespace

float fragmentTransmittance(const ParticleFragment& f) { return std::exp(-f.extinction * std::max(f.back - f.front, 0.0f)); }

BlendedLight blendOver(const ParticleFragment& f, const BlendedLight& behind) {
    const float t = fragmentTransmittance(f);
    return {f.colour * (1.0f - t) + t * behind.light, t * behind.transmittance};
}

ParticleFragment mergeOverlapping(const ParticleFragment& a, const ParticleFragment& b) {
    const ParticleFragment& first = a.front <= b.front ? a : b;  // owns the front stretch
    const ParticleFragment& last = a.back >= b.back ? a : b;     // owns the back stretch
    const float lo = first.front, hi = last.back;
    const float isecStart = std::max(a.front, b.front), isecEnd = std::max(std::min(a.back, b.back), isecStart);
    // Optical depths of the three stretches.
    const float tauFront = first.extinction * (isecStart - lo);
    const float sumExtinction = a.extinction + b.extinction;
    const float tauIsec = sumExtinction * (isecEnd - isecStart);
    const float tauBack = last.extinction * (hi - isecEnd);
    const glm::vec3 isecColour = sumExtinction > 0.0f ? (a.colour * a.extinction + b.colour * b.extinction) / sumExtinction : 0.5f * (a.colour + b.colour);
    const float tFront = std::exp(-tauFront), tIsec = std::exp(-tauIsec), tBack = std::exp(-tauBack);
    const float tau = tauFront + tauIsec + tauBack;
    const float opacity = 1.0f - tFront * tIsec * tBack;

    ParticleFragment merged;
    merged.front = lo;
    merged.back = hi;
    merged.extinction = hi > lo ? tau / (hi - lo) : 0.0f;
    if (opacity > kThinLimit) {
        const glm::vec3 cFront = first.colour * (1.0f - tFront), cIsec = isecColour * (1.0f - tIsec), cBack = last.colour * (1.0f - tBack);
        merged.colour = (cFront + cIsec * tFront + cBack * tFront * tIsec) / opacity;
    } else if (tau > 0.0f) {
        merged.colour = (first.colour * tauFront + isecColour * tauIsec + last.colour * tauBack) / tau;
    } else {
        merged.colour = 0.5f * (a.colour + b.colour);
    }
    return merged;
}

void VolumeBlend::add(const ParticleFragment& f) {
    if (!hasCurrent) {
        current = f;
        hasCurrent = true;
    } else if (f.back <= current.front) {
        behind = blendOver(current, behind);
        current = f;
    } else if (f.front >= current.back) {
        behind = blendOver(f, behind);
    } else {
        current = mergeOverlapping(current, f);
    }
}

BlendedLight VolumeBlend::resolve() const { return hasCurrent ? blendOver(current, behind) : behind; }

BlendedLight blendVolumes(std::vector<ParticleFragment> fragments, int maxFragments, int* dropped) {
    // Nearest first by the back distance, keep the nearest, then add from the farthest kept.
    std::stable_sort(fragments.begin(), fragments.end(), [](const ParticleFragment& x, const ParticleFragment& y) { return x.back < y.back; });
    const size_t kept = std::min(fragments.size(), static_cast<size_t>(std::max(maxFragments, 0)));
    if (dropped) *dropped = static_cast<int>(fragments.size() - kept);
    VolumeBlend blend;
    for (size_t k = kept; k-- > 0;) blend.add(fragments[k]);
    return blend.resolve();
}

BlendedLight blendAlpha(const std::vector<ParticleFragment>& backToFront) {
    BlendedLight result;
    for (const ParticleFragment& f : backToFront) result = blendOver(f, result);
    return result;
}

}  // namespace firmament
