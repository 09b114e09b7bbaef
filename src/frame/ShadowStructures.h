#pragma once
// The shadow cascades' constant-buffer structures, shared with HLSL: shaders/shadows/shadow_structures.hlsli, read here with HLSL's type
// names mapped to GLM (gpu/SharedStructures.h).
#include "gpu/SharedStructures.h"

namespace firmament::gpu {

#include "shadows/shadow_structures.hlsli"

}  // namespace firmament::gpu

namespace firmament {

// The most cascades the atlas holds: ShadowConstants carries a matrix for each.
inline constexpr int kMaxCascades = 8;
static_assert(sizeof(gpu::ShadowConstants::worldToShadow) == kMaxCascades * sizeof(gpu::ShadowConstants::worldToShadow[0]));

}  // namespace firmament
