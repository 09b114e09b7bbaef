#pragma once
// Draws Bruneton and Neyret 2008's atmosphere with its tables
// (shaders/atmosphere/bruneton/render.hlsl): sky, ground and sun composed as the paper does,
// in the same two parts as Yusov's model (the sky, with his ground and sun, where nothing was
// drawn; the aerial perspective over geometry: AtmospherePart), over the frame's columns it is given.
#include "atmosphere/AtmospherePart.h"
#include "atmosphere/bruneton/BrunetonPrecomputation.h"
#include "gpu/FullscreenPass.h"

namespace firmament {

class BrunetonPass {
public:
    explicit BrunetonPass(ID3D11Device* device);

    // `sceneRadiance`: a copy of the frame before this pass (the aerial perspective reads it).
    void render(ID3D11DeviceContext* context, ShaderLibrary& shaders, AtmospherePart part, const BrunetonPrecomputation& tables,
                ID3D11Buffer* frameConstants, ID3D11ShaderResourceView* sceneRadiance, ID3D11ShaderResourceView* depth, const Texture2D& target,
                Columns columns = {});

private:
    FullscreenPass fullscreen_;
    ConstantBuffer<gpu::AtmosphereConstants> atmosphere_;
    ConstantBuffer<gpu::BrunetonConstants> bruneton_;
    ConstantBuffer<gpu::BrunetonPassConstants> constants_;
    ComPtr<ID3D11SamplerState> linearClamp_;
};

}  // namespace firmament
