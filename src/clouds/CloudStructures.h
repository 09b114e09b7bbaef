#pragma once
// The clouds' structures, shared with HLSL: shaders/clouds/cloud_structures.hlsli, read here with
// HLSL's type names mapped to GLM (gpu/SharedStructures.h).
#include "gpu/SharedStructures.h"

namespace firmament::gpu {

#include "clouds/cloud_structures.hlsli"

// The particle as the GPU writes it (the HLSL struct CloudParticle).
struct CloudParticle {
    float4 centre;  // xyz: world position (m); w: horizontal radius (m)
    float4 shape;   // x: vertical radius (m); y: density; z: azimuth (radians); w: ring
};
static_assert(sizeof(CloudParticle) == 32, "CloudParticle is 32 bytes in HLSL");

}  // namespace firmament::gpu
