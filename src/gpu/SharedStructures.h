#pragma once
// The frame's constant-buffer structure shared with HLSL, shaders/common/shared_structures.hlsli,
// read here with HLSL's type names mapped to GLM; that header's static_asserts check that each
// structure is a multiple of 16 bytes. Each technique reads its own structures the same way
// (atmosphere/AtmosphereStructures.h, terrain/TerrainStructures.h, ...).
#include <glm/glm.hpp>

namespace firmament::gpu {

using float4 = glm::vec4;
using uint = glm::uint;
using uint4 = glm::uvec4;
using float4x4 = glm::mat4;

#include "common/shared_structures.hlsli"

static_assert(sizeof(float4) == 16 && sizeof(float4x4) == 64, "GLM types must be tightly packed");

}  // namespace firmament::gpu
