#pragma once
// What a pass that reads the cascaded shadow maps binds (shaders/shadows/cascade_sampling.hlsli).
#include <d3d11.h>

namespace firmament {

struct ShadowInputs {
    ID3D11Buffer* constants = nullptr;           // ShadowConstants (b4); mode.x == 0: no shadows
    ID3D11ShaderResourceView* map = nullptr;     // Texture2D<float>: the cascades' atlas (t4)
    ID3D11SamplerState* comparison = nullptr;    // LESS_EQUAL, bilinear (s2)
    int resolution = 0;                          // texels along a cascade's side
    int cascades = 0;                            // how many were drawn
};

}  // namespace firmament
