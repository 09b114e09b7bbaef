#pragma once
// The frame's log-average luminance (Reinhard et al. 2002, eq. 1) and the luminance the eye is
// adapted to, both on the GPU (Yusov 2013, "Tone mapping"):
//   1. measure(): ln(delta + L) of the HDR frame into a 64 x 64 R32F target; then, by Metering,
//      its mip chain down to 1 x 1, each level the mean of the one above
//      (shaders/postfx/log_luminance.hlsl, average_downsample.hlsl: Log average), or the mean
//      between two percentiles of its histogram, black left out (luminance_histogram.hlsl:
//      Histogram);
//   2. adapt(): a 1 x 1 R32F value that approaches the measured one exponentially with a time
//      constant (light_adaptation.hlsl). Two such textures alternate: last frame's is read
//      while this frame's is written.
// Everything stays in the log domain: the adapted value is ln of the adapted luminance.
#include "gpu/ConstantBuffer.h"
#include "gpu/FullscreenPass.h"
#include "postfx/PostfxStructures.h"
#include "postfx/ToneMappingSettings.h"
#include "gpu/Texture.h"

#include <array>

namespace firmament {

class SceneLuminance {
public:
    static constexpr int kSize = 64;       // the measurement target is kSize x kSize
    static constexpr int kMipLevels = 7;   // 64, 32, 16, 8, 4, 2, 1

    explicit SceneLuminance(ID3D11Device* device);

    void measure(ID3D11DeviceContext* context, ShaderLibrary& shaders, ID3D11ShaderResourceView* hdrFrame, int width, int height,
                 const ToneMappingSettings& settings);
    // `weight`: the fraction of the way to the measured value to go (LightAdaptation: 1 - exp(-dt / tau)).
    // The first call after construction or reset() takes the measured value whatever the weight.
    void adapt(ID3D11DeviceContext* context, ShaderLibrary& shaders, float weight);
    void reset() { reset_ = true; }

    // ln of the adapted luminance: 1 x 1 R32_FLOAT, valid after the first adapt().
    ID3D11ShaderResourceView* adaptedLogLuminance() const { return adapted_[current_].srv.Get(); }
    ID3D11Texture2D* adaptedLogLuminanceTexture() const { return adapted_[current_].texture.Get(); }
    // The last measurement's 64 x 64 texels of ln(delta + L), and its metered value (1 x 1) (tests).
    ID3D11Texture2D* logLuminanceTexture() const { return logLuminance_.Get(); }
    ID3D11Texture2D* measuredTexture() const { return metered_.texture.Get(); }

private:
    FullscreenPass fullscreen_;
    ConstantBuffer<gpu::SceneLuminanceConstants> constants_;
    ComPtr<ID3D11Texture2D> logLuminance_;
    std::array<ComPtr<ID3D11ShaderResourceView>, kMipLevels> levelViews_;
    std::array<ComPtr<ID3D11RenderTargetView>, kMipLevels> levelTargets_;
    Texture2D histogram_;  // 1 x 1 R32F: the histogram's metered ln(delta + L)
    Texture2D metered_;    // 1 x 1 R32F: this frame's measured value, whichever the metering
    std::array<Texture2D, 2> adapted_;
    int current_ = 0;
    bool reset_ = true;
};

}  // namespace firmament
