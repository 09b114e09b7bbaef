#pragma once
// How the clouds' particles are blended over the scene (docs/clouds.md, "Blending"): plain
// back-to-front alpha blending, or volume-aware blending (Yusov 2014) in pixel order, either
// through rasterizer-ordered views (the device's ROVsSupported; Intel's PixelSync) or through
// per-pixel fragment lists that a resolve pass sorts (the exact fallback, and the path Wine runs).
#include "clouds/CloudSettings.h"

#include <string_view>

namespace firmament {

enum class ParticleBlending { Alpha, RasterizerOrdered, PerPixelLists };

// What the device offers: D3D11_FEATURE_D3D11_OPTIONS2's ROVsSupported and
// TypedUAVLoadAdditionalFormats (the ordered path loads RGBA32F and RG32F views).
struct BlendingSupport {
    bool rasterizerOrderedViews = false;
    bool typedUavLoads = false;
};

// Volumetric blending off: alpha. On: the path asked for, rasterizer-ordered views only where the
// device supports them and their loads (otherwise the lists); Auto takes them where it can.
ParticleBlending chooseParticleBlending(bool volumetric, BlendingPath requested, BlendingSupport support);
std::string_view describeParticleBlending(ParticleBlending blending);

}  // namespace firmament
