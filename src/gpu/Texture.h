#pragma once
// A 2D texture with the views its bind flags ask for. Depth textures are typeless so that
// they can be both a depth-stencil view (D32_FLOAT) and a shader resource (R32_FLOAT).
#include <d3d11.h>
#include <wrl/client.h>

namespace firmament {

using Microsoft::WRL::ComPtr;

struct Texture2D {
    ComPtr<ID3D11Texture2D> texture;
    ComPtr<ID3D11RenderTargetView> rtv;
    ComPtr<ID3D11ShaderResourceView> srv;
    ComPtr<ID3D11UnorderedAccessView> uav;
    ComPtr<ID3D11DepthStencilView> dsv;
    int width = 0;
    int height = 0;
    DXGI_FORMAT format = DXGI_FORMAT_UNKNOWN;
};

// Colour texture: views for D3D11_BIND_RENDER_TARGET / SHADER_RESOURCE / UNORDERED_ACCESS.
Texture2D createColorTexture(ID3D11Device* device, int width, int height, DXGI_FORMAT format, UINT bindFlags);

// Depth buffer: 32-bit float depth, readable from shaders.
Texture2D createDepthTexture(ID3D11Device* device, int width, int height);

// A 3D texture (look-up tables) with the views its bind flags ask for (SHADER_RESOURCE,
// UNORDERED_ACCESS).
struct Texture3D {
    ComPtr<ID3D11Texture3D> texture;
    ComPtr<ID3D11ShaderResourceView> srv;
    ComPtr<ID3D11UnorderedAccessView> uav;
    int width = 0;
    int height = 0;
    int depth = 0;
};

Texture3D createTexture3D(ID3D11Device* device, int width, int height, int depth, DXGI_FORMAT format, UINT bindFlags);

}  // namespace firmament
