#pragma once
// Draws Yusov 2013's atmosphere into the HDR frame with its tables
// (shaders/atmosphere/yusov/render.hlsl), in two parts the renderer calls apart
// (AtmospherePart):
//  - the sky: where nothing was drawn, the light scattered along the whole ray and the sun's
//    disc through the atmosphere;
//  - the aerial perspective: over geometry, its radiance seen through the atmosphere plus the
//    light scattered in between (eq. 8). The light shafts replace this part.
#include "atmosphere/AtmospherePart.h"
#include "atmosphere/AtmosphereSettings.h"
#include "atmosphere/AtmosphereStructures.h"
#include "atmosphere/yusov/YusovPrecomputation.h"
#include "gpu/ConstantBuffer.h"
#include "gpu/FullscreenPass.h"
#include "gpu/Texture.h"

namespace firmament {

class YusovPass {
public:
    explicit YusovPass(ID3D11Device* device);

    // `sceneRadiance`: a copy of the frame before this pass (the aerial perspective reads it).
    void render(ID3D11DeviceContext* context, ShaderLibrary& shaders, AtmospherePart part, const AtmosphereSettings& settings,
                const YusovPrecomputation& tables, ID3D11Buffer* frameConstants, ID3D11ShaderResourceView* sceneRadiance,
                ID3D11ShaderResourceView* depth, const Texture2D& target, Columns columns = {});

    // The pass's constants for these settings: the scattering modes and the sun's disc.
    static gpu::YusovPassConstants constants(const AtmosphereSettings& settings);

private:
    FullscreenPass fullscreen_;
    ConstantBuffer<gpu::AtmosphereConstants> atmosphere_;
    ConstantBuffer<gpu::YusovPassConstants> constants_;
    ComPtr<ID3D11SamplerState> linearClamp_;
};

}  // namespace firmament
