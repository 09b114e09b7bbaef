#pragma once
// The HDR pipeline, frame order step 7: scene luminance, light adaptation and tone mapping to
// the display target. Owns its passes and their resources; docs/tonemapping.md explains it.
#include "core/ExrImage.h"
#include "frame/FrameContext.h"
#include "gpu/DelayedScalarReadback.h"
#include "postfx/ExposureReading.h"
#include "postfx/SceneLuminance.h"
#include "postfx/ToneMappingPass.h"

namespace firmament {

class ToneMapping {
public:
    explicit ToneMapping(ID3D11Device* device);

    // The frame's HDR target into `output`; light adaptation follows the frame's time step.
    void render(FrameContext& frame, const ToneMappingSettings& settings, ID3D11RenderTargetView* output);

    // A few frames old; never waits for the GPU (the GUI).
    ExposureReading latestReading(ID3D11DeviceContext* context, const ToneMappingSettings& settings);
    // This frame's; waits for the GPU (captures). Header attributes "firmament.toneMapping.*".
    ExrAttributes captureAttributes(ID3D11Device* device, ID3D11DeviceContext* context, const ToneMappingSettings& settings) const;

private:
    static ExposureReading reading(const ToneMappingSettings& settings, std::optional<float> adaptedLogLuminance);

    SceneLuminance luminance_;
    ToneMappingPass pass_;
    DelayedScalarReadback readback_;
    std::optional<float> latestLogLuminance_;
    bool measuring_ = false;  // auto exposure was on last frame
};

}  // namespace firmament
