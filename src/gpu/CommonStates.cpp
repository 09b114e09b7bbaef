#include "gpu/CommonStates.h"

#include "gpu/Hresult.h"

namespace firmament::states {

namespace {

ComPtr<ID3D11SamplerState> sampler(ID3D11Device* device, D3D11_FILTER filter, D3D11_TEXTURE_ADDRESS_MODE address,
                                   D3D11_COMPARISON_FUNC comparison, const char* what) {
    D3D11_SAMPLER_DESC desc{};
    desc.Filter = filter;
    desc.AddressU = desc.AddressV = desc.AddressW = address;
    desc.ComparisonFunc = comparison;
    desc.MaxLOD = D3D11_FLOAT32_MAX;
    ComPtr<ID3D11SamplerState> state;
    check(device->CreateSamplerState(&desc, &state), what);
    return state;
}

ComPtr<ID3D11RasterizerState> rasterizer(ID3D11Device* device, D3D11_CULL_MODE cull, bool scissor, float slopeScaledBias, bool depthClip,
                                         const char* what) {
    D3D11_RASTERIZER_DESC desc{};
    desc.FillMode = D3D11_FILL_SOLID;
    desc.CullMode = cull;
    desc.SlopeScaledDepthBias = slopeScaledBias;
    desc.DepthClipEnable = depthClip;
    desc.ScissorEnable = scissor;
    ComPtr<ID3D11RasterizerState> state;
    check(device->CreateRasterizerState(&desc, &state), what);
    return state;
}

ComPtr<ID3D11DepthStencilState> depthStencil(ID3D11Device* device, bool enable, D3D11_COMPARISON_FUNC test, const char* what) {
    D3D11_DEPTH_STENCIL_DESC desc{};
    desc.DepthEnable = enable;
    desc.DepthWriteMask = enable ? D3D11_DEPTH_WRITE_MASK_ALL : D3D11_DEPTH_WRITE_MASK_ZERO;
    desc.DepthFunc = enable ? test : D3D11_COMPARISON_ALWAYS;
    ComPtr<ID3D11DepthStencilState> state;
    check(device->CreateDepthStencilState(&desc, &state), what);
    return state;
}

}  // namespace

ComPtr<ID3D11BlendState> noColourWrites(ID3D11Device* device) {
    D3D11_BLEND_DESC desc{};
    desc.RenderTarget[0].SrcBlend = D3D11_BLEND_ONE;
    desc.RenderTarget[0].DestBlend = D3D11_BLEND_ZERO;
    desc.RenderTarget[0].BlendOp = D3D11_BLEND_OP_ADD;
    desc.RenderTarget[0].SrcBlendAlpha = D3D11_BLEND_ONE;
    desc.RenderTarget[0].DestBlendAlpha = D3D11_BLEND_ZERO;
    desc.RenderTarget[0].BlendOpAlpha = D3D11_BLEND_OP_ADD;
    desc.RenderTarget[0].RenderTargetWriteMask = 0;
    ComPtr<ID3D11BlendState> state;
    check(device->CreateBlendState(&desc, &state), "CreateBlendState (no colour writes)");
    return state;
}

ComPtr<ID3D11BlendState> minimumColourProductAlpha(ID3D11Device* device) {
    D3D11_BLEND_DESC desc{};
    D3D11_RENDER_TARGET_BLEND_DESC& target = desc.RenderTarget[0];
    target.BlendEnable = TRUE;
    target.SrcBlend = D3D11_BLEND_ONE;
    target.DestBlend = D3D11_BLEND_ONE;
    target.BlendOp = D3D11_BLEND_OP_MIN;
    target.SrcBlendAlpha = D3D11_BLEND_ZERO;
    target.DestBlendAlpha = D3D11_BLEND_SRC_ALPHA;
    target.BlendOpAlpha = D3D11_BLEND_OP_ADD;
    target.RenderTargetWriteMask = D3D11_COLOR_WRITE_ENABLE_ALL;
    ComPtr<ID3D11BlendState> state;
    check(device->CreateBlendState(&desc, &state), "CreateBlendState (minimum colour, product alpha)");
    return state;
}

// Premultiplied colour (src + (1 - src.a) dst), the target's alpha scaled by `destinationAlpha`.
ComPtr<ID3D11BlendState> premultipliedColour(ID3D11Device* device, D3D11_BLEND destinationAlpha, const char* what) {
    D3D11_BLEND_DESC desc{};
    D3D11_RENDER_TARGET_BLEND_DESC& target = desc.RenderTarget[0];
    target.BlendEnable = TRUE;
    target.SrcBlend = D3D11_BLEND_ONE;
    target.DestBlend = D3D11_BLEND_INV_SRC_ALPHA;
    target.BlendOp = D3D11_BLEND_OP_ADD;
    target.SrcBlendAlpha = D3D11_BLEND_ZERO;
    target.DestBlendAlpha = destinationAlpha;
    target.BlendOpAlpha = D3D11_BLEND_OP_ADD;
    target.RenderTargetWriteMask = D3D11_COLOR_WRITE_ENABLE_ALL;
    ComPtr<ID3D11BlendState> state;
    check(device->CreateBlendState(&desc, &state), what);
    return state;
}

ComPtr<ID3D11BlendState> premultipliedAlpha(ID3D11Device* device) {
    return premultipliedColour(device, D3D11_BLEND_ONE, "CreateBlendState (premultiplied alpha)");
}

ComPtr<ID3D11BlendState> premultipliedAlphaTransmittance(ID3D11Device* device) {
    return premultipliedColour(device, D3D11_BLEND_INV_SRC_ALPHA, "CreateBlendState (premultiplied alpha, transmittance)");
}

ComPtr<ID3D11SamplerState> linearClamp(ID3D11Device* device) {
    return sampler(device, D3D11_FILTER_MIN_MAG_MIP_LINEAR, D3D11_TEXTURE_ADDRESS_CLAMP, D3D11_COMPARISON_NEVER, "CreateSamplerState (linear clamp)");
}

ComPtr<ID3D11SamplerState> linearWrap(ID3D11Device* device) {
    return sampler(device, D3D11_FILTER_MIN_MAG_MIP_LINEAR, D3D11_TEXTURE_ADDRESS_WRAP, D3D11_COMPARISON_NEVER, "CreateSamplerState (linear wrap)");
}

ComPtr<ID3D11SamplerState> shadowComparison(ID3D11Device* device) {
    return sampler(device, D3D11_FILTER_COMPARISON_MIN_MAG_LINEAR_MIP_POINT, D3D11_TEXTURE_ADDRESS_CLAMP, D3D11_COMPARISON_LESS_EQUAL,
                   "CreateSamplerState (shadow comparison)");
}

ComPtr<ID3D11RasterizerState> cullNone(ID3D11Device* device) {
    return rasterizer(device, D3D11_CULL_NONE, false, 0.0f, true, "CreateRasterizerState (cull none)");
}

ComPtr<ID3D11RasterizerState> cullBack(ID3D11Device* device) {
    return rasterizer(device, D3D11_CULL_BACK, false, 0.0f, true, "CreateRasterizerState (cull back)");
}

ComPtr<ID3D11RasterizerState> cullBackScissored(ID3D11Device* device) {
    return rasterizer(device, D3D11_CULL_BACK, true, 0.0f, true, "CreateRasterizerState (cull back, scissored)");
}

ComPtr<ID3D11RasterizerState> cullNoneScissored(ID3D11Device* device) {
    return rasterizer(device, D3D11_CULL_NONE, true, 0.0f, true, "CreateRasterizerState (cull none, scissored)");
}

ComPtr<ID3D11RasterizerState> shadowCaster(ID3D11Device* device, float slopeScaledBias) {
    return rasterizer(device, D3D11_CULL_NONE, false, slopeScaledBias, false, "CreateRasterizerState (shadow casters)");
}

ComPtr<ID3D11DepthStencilState> depthNone(ID3D11Device* device) {
    return depthStencil(device, false, D3D11_COMPARISON_ALWAYS, "CreateDepthStencilState (no depth)");
}

ComPtr<ID3D11DepthStencilState> depthReversed(ID3D11Device* device) {
    return depthStencil(device, true, D3D11_COMPARISON_GREATER_EQUAL, "CreateDepthStencilState (reversed Z)");
}

ComPtr<ID3D11DepthStencilState> depthLess(ID3D11Device* device) {
    return depthStencil(device, true, D3D11_COMPARISON_LESS, "CreateDepthStencilState (less)");
}

}  // namespace firmament::states
