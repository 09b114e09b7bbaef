#pragma once
// Draws Bruneton and Neyret 2008's atmosphere with its tables
// (shaders/atmosphere/bruneton/render.hlsl): sky, ground and sun composed as the paper does,
// in the same two parts as Yusov's model (the sky, with his ground and sun, where nothing was
// drawn; the aerial perspective over geometry: AtmospherePart), over the whole frame, over its right part (the split view), or as the
// absolute difference from what another model drew (the difference view).
#include "atmosphere/AtmospherePart.h"
#include "atmosphere/bruneton/BrunetonPrecomputation.h"
#include "gpu/FullscreenPass.h"

namespace firmament {

enum class BrunetonView : unsigned { WholeFrame = 0, RightOfColumn = 1, DifferenceFromOther = 2 };

// Where and how the model draws: `firstColumn` is where RightOfColumn starts; `otherModel` is
// the frame to subtract (DifferenceFromOther only).
struct BrunetonComposition {
    BrunetonView view = BrunetonView::WholeFrame;
    unsigned firstColumn = 0;
    ID3D11ShaderResourceView* otherModel = nullptr;
};

class BrunetonPass {
public:
    explicit BrunetonPass(ID3D11Device* device);

    // `sceneRadiance`: a copy of the frame before this pass (the aerial perspective reads it).
    void render(ID3D11DeviceContext* context, ShaderLibrary& shaders, AtmospherePart part, const BrunetonPrecomputation& tables,
                ID3D11Buffer* frameConstants, ID3D11ShaderResourceView* sceneRadiance, ID3D11ShaderResourceView* depth, const Texture2D& target,
                const BrunetonComposition& composition);

private:
    FullscreenPass fullscreen_;
    ConstantBuffer<gpu::AtmosphereConstants> atmosphere_;
    ConstantBuffer<gpu::BrunetonConstants> bruneton_;
    ConstantBuffer<gpu::BrunetonPassConstants> constants_;
    ComPtr<ID3D11SamplerState> linearClamp_;
};

}  // namespace firmament
