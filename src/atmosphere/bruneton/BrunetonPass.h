#pragma once
// Draws the atmosphere with Bruneton and Neyret 2008's tables
// (shaders/atmosphere/bruneton/render.hlsl): sky, ground and sun composed as document 002
// does, over the whole frame, over its right part (the split view), or as the absolute
// difference from what another model drew (the difference view).
#include "atmosphere/bruneton/BrunetonPrecomputation.h"
#include "gpu/FullscreenPass.h"

namespace firmament {

enum class BrunetonView : unsigned { WholeFrame = 0, RightOfColumn = 1, DifferenceFromOther = 2 };

class BrunetonPass {
public:
    explicit BrunetonPass(ID3D11Device* device);

    // `sceneRadiance`: the frame before the atmosphere; `otherModel`: the frame to subtract
    // (DifferenceFromOther only); `firstColumn`: where RightOfColumn starts.
    void render(ID3D11DeviceContext* context, ShaderLibrary& shaders, const BrunetonPrecomputation& tables, ID3D11Buffer* frameConstants,
                ID3D11ShaderResourceView* sceneRadiance, ID3D11ShaderResourceView* depth, const Texture2D& target, BrunetonView view,
                unsigned firstColumn = 0, ID3D11ShaderResourceView* otherModel = nullptr);

private:
    FullscreenPass fullscreen_;
    ConstantBuffer<gpu::AtmosphereConstants> atmosphere_;
    ConstantBuffer<gpu::BrunetonConstants> bruneton_;
    ConstantBuffer<gpu::BrunetonPassConstants> constants_;
    ComPtr<ID3D11SamplerState> linearClamp_;
};

}  // namespace firmament
