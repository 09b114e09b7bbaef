#pragma once
// The shadow cascades' constant-buffer structures, shared with HLSL: shaders/shadows/shadow_structures.hlsli, read here with HLSL's type
// names mapped to GLM (gpu/SharedStructures.h).
#include "gpu/SharedStructures.h"

namespace firmament::gpu {

#include "shadows/shadow_structures.hlsli"

}  // namespace firmament::gpu
