#pragma once
// The light shafts' constant-buffer structures, shared with HLSL: shaders/lightshafts/lightshaft_structures.hlsli, read here with
// HLSL's type names mapped to GLM (gpu/SharedStructures.h).
#include "gpu/SharedStructures.h"

namespace firmament::gpu {

#include "lightshafts/lightshaft_structures.hlsli"

}  // namespace firmament::gpu
