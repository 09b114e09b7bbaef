#pragma once
// The HDR pipeline's constant-buffer structures, shared with HLSL: shaders/postfx/postfx_structures.hlsli, read here with HLSL's type
// names mapped to GLM (gpu/SharedStructures.h).
#include "gpu/SharedStructures.h"

namespace firmament::gpu {

#include "postfx/postfx_structures.hlsli"

}  // namespace firmament::gpu
