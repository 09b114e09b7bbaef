#pragma once
// The HDR frame to the display target: exposure (manual, or from the adapted log-average
// luminance), one of the seven operators, sRGB encoding (shaders/postfx/tone_mapping.hlsl).
// The output is display-encoded values: an 8-bit UNORM target (the back buffer) quantises
// them, a float target (the tests) keeps them as computed.
#include "gpu/ConstantBuffer.h"
#include "gpu/FullscreenPass.h"
#include "postfx/PostfxStructures.h"
#include "postfx/ToneMappingSettings.h"

namespace firmament {

class ToneMappingPass {
public:
    explicit ToneMappingPass(ID3D11Device* device);

    // `adaptedLogLuminance`: 1 x 1, ln of the adapted average (read only with auto exposure).
    void render(ID3D11DeviceContext* context, ShaderLibrary& shaders, const ToneMappingSettings& settings,
                ID3D11ShaderResourceView* hdrFrame, ID3D11ShaderResourceView* adaptedLogLuminance,
                ID3D11RenderTargetView* output, int width, int height);

private:
    FullscreenPass fullscreen_;
    ConstantBuffer<gpu::ToneMappingConstants> constants_;
};

}  // namespace firmament
