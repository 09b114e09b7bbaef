#pragma once
// The atmosphere's constant-buffer structures, shared with HLSL: shaders/atmosphere/atmosphere_structures.hlsli, read here with HLSL's type
// names mapped to GLM (gpu/SharedStructures.h).
#include "gpu/SharedStructures.h"

namespace firmament::gpu {

#include "atmosphere/atmosphere_structures.hlsli"

}  // namespace firmament::gpu
