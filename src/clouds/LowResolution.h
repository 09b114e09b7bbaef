#pragma once
// The clouds rendered at a fraction of the frame's resolution (Downscale 2x or 4x; Yusov 2014,
// "Low-resolution rendering"; docs/clouds.md): the scene's depth brought down to that resolution
// (each pixel the nearest of its block), a target for the clouds' premultiplied light and their
// transmittance, and the bilateral upsample by depth that blends them over the frame with sharp
// edges against the terrain and the sky.
#include "clouds/CloudStructures.h"
#include "gpu/ConstantBuffer.h"
#include "gpu/FullscreenPass.h"
#include "gpu/Texture.h"

#include <d3d11.h>

namespace firmament {

class ShaderLibrary;

class CloudLowResolution {
public:
    explicit CloudLowResolution(ID3D11Device* device);

    // The low resolution of a width x height frame at `factor` (each side rounded up).
    static int lowSize(int size, int factor) { return (size + factor - 1) / factor; }

    // Sizes the targets for `factor` (2 or 4), writes the low-resolution depth from the frame's
    // `sceneDepth` and clears the clouds' target to no light and transmittance 1.
    void begin(ID3D11Device* device, ID3D11DeviceContext* context, ShaderLibrary& shaders, ID3D11ShaderResourceView* sceneDepth, int width,
               int height, int factor);
    // The clouds' target (RGBA16F: premultiplied light; alpha, the transmittance) and the depth
    // the particles are cut by (R32_FLOAT, reversed).
    const Texture2D& clouds() const { return clouds_; }
    const Texture2D& depth() const { return depth_; }
    // Premultiplied alpha that multiplies the target's alpha by each layer's transmittance.
    ID3D11BlendState* blendState() const { return transmittance_.Get(); }
    // Blends the clouds over `target` (width x height, the frame's `sceneDepth`).
    void upsample(ID3D11DeviceContext* context, ShaderLibrary& shaders, ID3D11ShaderResourceView* sceneDepth, ID3D11RenderTargetView* target,
                  int width, int height);

private:
    FullscreenPass fullscreen_;
    ConstantBuffer<gpu::CloudUpsampleConstants> constants_;
    ComPtr<ID3D11BlendState> transmittance_;
    ComPtr<ID3D11BlendState> premultiplied_;
    Texture2D clouds_;
    Texture2D depth_;
    int factor_ = 0;
};

}  // namespace firmament
