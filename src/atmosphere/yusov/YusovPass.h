#pragma once
// Draws Yusov 2013's atmosphere into the HDR frame with its tables
// (shaders/atmosphere/yusov/render.hlsl), as two passes the renderer calls apart:
//  - the sky: where nothing was drawn, the light scattered along the whole ray and the sun's
//    disc through the atmosphere;
//  - the aerial perspective: over geometry, its radiance seen through the atmosphere plus the
//    light scattered in between (eq. 8). The light shafts replace this pass.
#include "atmosphere/AtmosphereSettings.h"
#include "atmosphere/yusov/YusovPrecomputation.h"
#include "gpu/ConstantBuffer.h"
#include "gpu/FullscreenPass.h"
#include "gpu/SharedStructures.h"
#include "gpu/Texture.h"

namespace firmament {

class YusovPass {
public:
    explicit YusovPass(ID3D11Device* device);

    // Where the depth is at the far plane: the sky, the sun, or space.
    void renderSky(ID3D11DeviceContext* context, ShaderLibrary& shaders, const AtmosphereSettings& settings, const YusovPrecomputation& tables,
                   ID3D11Buffer* frameConstants, ID3D11ShaderResourceView* depth, const Texture2D& target);
    // Where geometry was drawn: `sceneRadiance` is the frame before this pass (a copy of it).
    void renderAerialPerspective(ID3D11DeviceContext* context, ShaderLibrary& shaders, const AtmosphereSettings& settings,
                                 const YusovPrecomputation& tables, ID3D11Buffer* frameConstants, ID3D11ShaderResourceView* sceneRadiance,
                                 ID3D11ShaderResourceView* depth, const Texture2D& target);

    // The pass's constants for these settings: the scattering modes and the sun's disc.
    static gpu::YusovPassConstants constants(const AtmosphereSettings& settings);

private:
    void draw(ID3D11DeviceContext* context, ShaderLibrary& shaders, const ShaderKey& pixelShader, const AtmosphereSettings& settings,
              const YusovPrecomputation& tables, ID3D11Buffer* frameConstants, ID3D11ShaderResourceView* sceneRadiance,
              ID3D11ShaderResourceView* depth, const Texture2D& target);

    FullscreenPass fullscreen_;
    ConstantBuffer<gpu::AtmosphereConstants> atmosphere_;
    ConstantBuffer<gpu::YusovPassConstants> constants_;
    ComPtr<ID3D11SamplerState> linearClamp_;
};

}  // namespace firmament
