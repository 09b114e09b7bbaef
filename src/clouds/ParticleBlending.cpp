#include "clouds/ParticleBlending.h"

namespace firmament {

ParticleBlending chooseParticleBlending(bool volumetric, BlendingPath requested, BlendingSupport support) {
    if (!volumetric) return ParticleBlending::Alpha;
    const bool ordered = support.rasterizerOrderedViews && support.typedUavLoads;
    if (requested == BlendingPath::PerPixelLists || !ordered) return ParticleBlending::PerPixelLists;
    return ParticleBlending::RasterizerOrdered;
}

std::string_view describeParticleBlending(ParticleBlending blending) {
    switch (blending) {
    case ParticleBlending::Alpha: return "alpha blending";
    case ParticleBlending::RasterizerOrdered: return "volume-aware, rasterizer-ordered views";
    case ParticleBlending::PerPixelLists: return "volume-aware, per-pixel lists";
    }
    return "unknown";
}

}  // namespace firmament
