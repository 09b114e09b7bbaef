#include "gpu/FullscreenPass.h"

#include "gpu/CommonStates.h"

#include <algorithm>

namespace firmament {

FullscreenPass::FullscreenPass(ID3D11Device* device)
    : rasterizer_(states::cullNone(device)), scissored_(states::cullNoneScissored(device)), noDepth_(states::depthNone(device)) {}

void FullscreenPass::bindTarget(ID3D11DeviceContext* context, ID3D11RenderTargetView* target, int width, int height, Columns columns) const {
    const D3D11_VIEWPORT viewport{0.0f, 0.0f, static_cast<float>(width), static_cast<float>(height), 0.0f, 1.0f};
    context->OMSetRenderTargets(1, &target, nullptr);
    context->OMSetDepthStencilState(noDepth_.Get(), 0);
    context->OMSetBlendState(nullptr, nullptr, 0xffffffff);
    const bool part = columns.first > 0 || columns.end < width;
    context->RSSetState(part ? scissored_.Get() : rasterizer_.Get());
    if (part) {
        const D3D11_RECT rect{std::clamp(columns.first, 0, width), 0, std::clamp(columns.end, 0, width), height};
        context->RSSetScissorRects(1, &rect);
    }
    context->RSSetViewports(1, &viewport);
    context->IASetInputLayout(nullptr);
    context->IASetPrimitiveTopology(D3D11_PRIMITIVE_TOPOLOGY_TRIANGLELIST);
}

void FullscreenPass::draw(ID3D11DeviceContext* context, ShaderLibrary& shaders, const ShaderKey& vertexShader,
                          const ShaderKey& pixelShader) const {
    context->VSSetShader(shaders.vertexShader(vertexShader), nullptr, 0);
    context->PSSetShader(shaders.pixelShader(pixelShader), nullptr, 0);
    context->Draw(3, 0);
}

void FullscreenPass::draw(ID3D11DeviceContext* context, ShaderLibrary& shaders, const ShaderKey& vertexShader, const ShaderKey& pixelShader,
                          std::initializer_list<ID3D11Buffer*> constants, std::initializer_list<ID3D11ShaderResourceView*> inputs,
                          ID3D11SamplerState* sampler) const {
    context->PSSetConstantBuffers(0, static_cast<UINT>(constants.size()), constants.begin());
    context->PSSetShaderResources(0, static_cast<UINT>(inputs.size()), inputs.begin());
    context->PSSetSamplers(0, 1, &sampler);
    draw(context, shaders, vertexShader, pixelShader);
    ID3D11ShaderResourceView* none[D3D11_COMMONSHADER_INPUT_RESOURCE_SLOT_COUNT] = {};
    context->PSSetShaderResources(0, static_cast<UINT>(inputs.size()), none);
}

}  // namespace firmament
