#ifndef FIRMAMENT_HILLAIRE_CAMERA_TABLES_HLSLI
#define FIRMAMENT_HILLAIRE_CAMERA_TABLES_HLSLI
// What the two tables that follow the camera (sky_view.hlsl, aerial_perspective.hlsl) bind alike:
// the frame's, the atmosphere's and the model's constants (b0 to b2), the camera-independent
// tables (t0, t1) and their sampler (s0). src/atmosphere/hillaire/HillairePass binds them.
#include "atmosphere/hillaire/camera.hlsli"

cbuffer FrameBuffer : register(b0) {
    FrameConstants frame;
};
cbuffer AtmosphereBuffer : register(b1) {
    AtmosphereConstants atmosphere;
};
cbuffer HillaireBuffer : register(b2) {
    HillaireConstants hillaire;
};
Texture2D<float4> transmittanceTable : register(t0);
Texture2D<float4> multipleScatteringTable : register(t1);
SamplerState linearClamp : register(s0);

// The march of march.hlsli over these tables.
HillaireSegment marchView(HillaireView v, float t0, float t1, int steps, bool squared, HillaireSegment segment) {
    return hillaireMarch(atmosphere, hillaire, transmittanceTable, multipleScatteringTable, linearClamp, v, t0, t1, steps, squared, segment);
}

#endif
