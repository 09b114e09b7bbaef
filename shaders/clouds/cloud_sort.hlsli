#ifndef FIRMAMENT_CLOUD_SORT_HLSLI
#define FIRMAMENT_CLOUD_SORT_HLSLI
// The particles' back-to-front order (docs/clouds.md, "Sort"): keys are (distance bits, slot);
// a non-negative float's bits order like the float, and the slot breaks ties.
#include "clouds/cloud_field.hlsli"

Buffer<uint> particleArguments : register(t0);  // the particles' count at [3]

// Whether key a is drawn before key b: the farther first.
bool drawnBefore(uint2 a, uint2 b) { return a.x > b.x || (a.x == b.x && a.y < b.y); }

uint particleCount() { return min(particleArguments[3], field.centre.z); }

#endif
