#pragma once
// What a pass that reads the clouds' light-space transparency map binds
// (shaders/shadows/cloud_shadow.hlsli; the map is src/clouds/CloudShadowMap.h's).
#include <d3d11.h>

namespace firmament {

struct CloudShadowInputs {
    ID3D11Buffer* constants = nullptr;        // CloudShadowConstants; up.w == 0: no cloud shadows
    ID3D11ShaderResourceView* map = nullptr;  // Texture2D<float4>: (far, -near, 0, transmittance) per texel
};

}  // namespace firmament
