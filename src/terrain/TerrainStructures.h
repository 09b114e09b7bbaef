#pragma once
// The terrain's constant-buffer structures, shared with HLSL: shaders/terrain/terrain_structures.hlsli, read here with HLSL's type
// names mapped to GLM (gpu/SharedStructures.h).
#include "gpu/SharedStructures.h"

namespace firmament::gpu {

#include "terrain/terrain_structures.hlsli"

}  // namespace firmament::gpu
