#pragma once
// The Direct3D 11 state objects Firmament's passes use, each described once, in the manner of
// DirectXTK's CommonStates. Every call creates (or, for an identical description, gets back
// from the runtime's cache) the state; a technique keeps the ones it binds.
#include <d3d11.h>
#include <wrl/client.h>

namespace firmament::states {

using Microsoft::WRL::ComPtr;

// Samplers.
ComPtr<ID3D11SamplerState> linearClamp(ID3D11Device* device);  // trilinear, clamped: every table look-up
ComPtr<ID3D11SamplerState> linearWrap(ID3D11Device* device);   // trilinear, wrapped: tiling fields (the terrain's)
// Bilinear depth comparison (LESS_EQUAL: lit where the stored depth is not nearer), clamped:
// percentage-closer filtering of shadow maps.
ComPtr<ID3D11SamplerState> shadowComparison(ID3D11Device* device);

// Rasterizer states, all solid and depth-clipped unless said otherwise.
ComPtr<ID3D11RasterizerState> cullNone(ID3D11Device* device);
ComPtr<ID3D11RasterizerState> cullBack(ID3D11Device* device);  // clockwise triangles are the front
// Back-face culling, or none, inside the scissor rectangle (a pass drawn over part of the frame).
ComPtr<ID3D11RasterizerState> cullBackScissored(ID3D11Device* device);
ComPtr<ID3D11RasterizerState> cullNoneScissored(ID3D11Device* device);
// Shadow casters: no culling, a slope-scaled depth bias, and no depth clipping, so that casters
// nearer the light than the cascade's range clamp to its near plane and still cast.
ComPtr<ID3D11RasterizerState> shadowCaster(ID3D11Device* device, float slopeScaledBias);

// Blend states.
// Premultiplied alpha over what is there: dst = src.rgb + (1 - src.a) dst.rgb (translucent
// layers drawn back to front); the target's alpha is kept.
ComPtr<ID3D11BlendState> premultipliedAlpha(ID3D11Device* device);
// The same, with the target's alpha multiplied by each layer's transmittance (1 - src.a): cleared
// to 1, it ends as the transmittance through every layer.
ComPtr<ID3D11BlendState> premultipliedAlphaTransmittance(ID3D11Device* device);
// Writes no colour: for pixel shaders that only write views, with the target bound so that the
// pass has the target's size (Wine otherwise draws into whichever framebuffer it last had bound).
ComPtr<ID3D11BlendState> noColourWrites(ID3D11Device* device);
// The smallest colour kept (dst.rgb = min(src.rgb, dst.rgb)), the alpha multiplied
// (dst.a = src.a dst.a): layers drawn in any order keep their nearest extents and the product of
// their transmittances.
ComPtr<ID3D11BlendState> minimumColourProductAlpha(ID3D11Device* device);

// Depth-stencil states. Firmament's depth is reversed (1 at the near plane, 0 at the far one,
// cleared to 0; src/core/Camera.h), so "nearer or equal" is GREATER_EQUAL.
ComPtr<ID3D11DepthStencilState> depthNone(ID3D11Device* device);            // no test, no write
ComPtr<ID3D11DepthStencilState> depthReversed(ID3D11Device* device);        // test GREATER_EQUAL and write
ComPtr<ID3D11DepthStencilState> depthLess(ID3D11Device* device);            // test LESS and write (shadow maps keep standard depth)

}  // namespace firmament::states
