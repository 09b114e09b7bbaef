#pragma once
// The pipeline state every full-screen pass shares: one triangle from SV_VertexID
// (shaders/common/fullscreen_triangle.hlsli), no depth, no blending, no culling. A pass
// calls bindTarget(), then binds its own constants and resources, then calls draw(). The
// target comes first: binding it unbinds any view of the same texture still bound as an
// input, so a texture that was the previous pass's target must be bound after it.
#include "gpu/ShaderLibrary.h"

#include <d3d11.h>

#include <initializer_list>

namespace firmament {

// The columns [first, end) of a target a pass draws (clipped to the target): a comparison of
// atmosphere models draws each in its own.
struct Columns {
    int first = 0;
    int end = 1 << 30;
};

class FullscreenPass {
public:
    explicit FullscreenPass(ID3D11Device* device);

    // Sets the target, the viewport and the fixed-function states; the pass draws `columns` only.
    void bindTarget(ID3D11DeviceContext* context, ID3D11RenderTargetView* target, int width, int height, Columns columns = {}) const;
    // Sets the two shaders and draws the triangle.
    void draw(ID3D11DeviceContext* context, ShaderLibrary& shaders, const ShaderKey& vertexShader,
              const ShaderKey& pixelShader) const;
    // The same, binding the pixel shader's constant buffers (from b0), inputs (from t0) and
    // sampler (s0) first, and unbinding the inputs after, so that a later pass may write them.
    void draw(ID3D11DeviceContext* context, ShaderLibrary& shaders, const ShaderKey& vertexShader, const ShaderKey& pixelShader,
              std::initializer_list<ID3D11Buffer*> constants, std::initializer_list<ID3D11ShaderResourceView*> inputs,
              ID3D11SamplerState* sampler) const;

private:
    ComPtr<ID3D11RasterizerState> rasterizer_, scissored_;
    ComPtr<ID3D11DepthStencilState> noDepth_;
};

}  // namespace firmament
