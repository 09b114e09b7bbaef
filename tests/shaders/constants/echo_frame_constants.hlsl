// Copies the FrameConstants constant buffer, as HLSL lays it out, into a buffer of floats,
// so the test can compare it with the C++ structure from the same header.
// The shared header lives under the program's shader root; this path works from the test
// shader root for vkd3d-compiler (relative to its working folder) and for FXC (through /I).
#include "../../shaders/common/shared_structures.hlsli"

cbuffer FrameBuffer : register(b0) {
    FrameConstants frame;
};

RWStructuredBuffer<float4> echoed : register(u0);

[numthreads(1, 1, 1)]
void main() {
    for (uint row = 0; row < 4; ++row) {
        echoed[row] = frame.viewProjection[row];
        echoed[4 + row] = frame.inverseViewProjection[row];
        echoed[8 + row] = frame.clipToDirection[row];
    }
    echoed[12] = frame.cameraPosition;
    echoed[13] = frame.directionToSun;
    echoed[14] = frame.screen;
    echoed[15] = frame.time;
    echoed[16] = frame.sunIrradiance;
    echoed[17] = frame.planet;
}
