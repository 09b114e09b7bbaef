// The indirect arguments of the passes over the valid cells and over the particles, from their
// counts (src/clouds/CloudParticles.h): thread groups for a dispatch, and the instanced draw of
// the particles' bounding shapes.
#include "clouds/cloud_field.hlsli"

// Four components per element, though the view is R32_UINT: Wine's translation of a typed store
// of a single constant makes GLSL that does not compile (docs/building.md).
RWBuffer<uint4> argumentsOut : register(u0);

// Over the valid cells: groups of 64 (generate_particles.hlsl).
[numthreads(1, 1, 1)]
void cells() {
    uint count = argumentsOut[3].x;
    argumentsOut[0] = uint4((count + 63u) / 64u, 0, 0, 0);
    argumentsOut[1] = uint4(1, 0, 0, 0);
    argumentsOut[2] = uint4(1, 0, 0, 0);
}

// Over the particles, at most the capacity: groups of 256 (the sort's passes), then
// DrawInstanced's vertices per instance, instances, first vertex and first instance.
[numthreads(1, 1, 1)]
void particles() {
    uint count = min(argumentsOut[3].x, field.centre.z);
    argumentsOut[0] = uint4((count + 255u) / 256u, 0, 0, 0);
    argumentsOut[1] = uint4(1, 0, 0, 0);
    argumentsOut[2] = uint4(1, 0, 0, 0);
    argumentsOut[4] = uint4(4, 0, 0, 0);
    argumentsOut[5] = uint4(count, 0, 0, 0);
    argumentsOut[6] = uint4(0, 0, 0, 0);
    argumentsOut[7] = uint4(0, 0, 0, 0);
}
