#pragma once
// Writes the HDR frame to the 8-bit output target, scaled by the exposure, clamped and sRGB
// encoded (shaders/postfx/display_encode.hlsl). Tone mapping will take its place in the frame.
#include "gpu/ConstantBuffer.h"
#include "gpu/FullscreenPass.h"
#include "gpu/ShaderLibrary.h"
#include "gpu/SharedStructures.h"
#include "postfx/ToneMappingSettings.h"

#include <d3d11.h>

namespace firmament {

class DisplayEncodePass {
public:
    explicit DisplayEncodePass(ID3D11Device* device);

    void render(ID3D11DeviceContext* context, ShaderLibrary& shaders, const ToneMappingSettings& settings,
                ID3D11ShaderResourceView* hdrFrame, ID3D11RenderTargetView* output, int width, int height);

private:
    FullscreenPass fullscreen_;
    ConstantBuffer<gpu::DisplayEncodeConstants> constants_;
};

}  // namespace firmament
