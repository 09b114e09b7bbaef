#include "postfx/ToneMapping.h"

#include "gpu/Readback.h"
#include "postfx/ToneMappingCurves.h"

#include <cmath>
#include <cstring>
#include <string>

namespace firmament {

ToneMapping::ToneMapping(ID3D11Device* device) : luminance_(device), pass_(device), readback_(device) {}

void ToneMapping::render(FrameContext& frame, const ToneMappingSettings& settings, ID3D11RenderTargetView* output) {
    ID3D11DeviceContext* context = frame.context;
    ShaderLibrary& shaders = frame.shaders;
    GpuProfiler& profiler = frame.profiler;
    ID3D11ShaderResourceView* hdrFrame = frame.targets.hdr().srv.Get();
    const int width = frame.width(), height = frame.height();
    const double dtSeconds = frame.dtSeconds;
    if (settings.autoExposure) {
        if (!measuring_) {  // switched on: start from this frame's measurement, forget the old reading
            luminance_.reset();
            latestLogLuminance_.reset();
        }
        {
            auto pass = profiler.scope("Scene luminance");
            luminance_.measure(context, shaders, hdrFrame, width, height, settings);
        }
        {
            auto pass = profiler.scope("Light adaptation");
            const double weight = settings.lightAdaptation ? tonemap::adaptationWeight(dtSeconds, settings.adaptationSeconds) : 1.0;
            luminance_.adapt(context, shaders, static_cast<float>(weight));
        }
        readback_.copy(context, luminance_.adaptedLogLuminanceTexture());
    }
    measuring_ = settings.autoExposure;
    auto pass = profiler.scope("Tone mapping");
    pass_.render(context, shaders, settings, hdrFrame, luminance_.adaptedLogLuminance(), output, width, height);
}

ExposureReading ToneMapping::reading(const ToneMappingSettings& settings, std::optional<float> adaptedLogLuminance) {
    ExposureReading r;
    if (!settings.autoExposure) {
        r.exposure = settings.exposureCompensation();
        return r;
    }
    if (!adaptedLogLuminance) return r;
    r.measured = true;
    r.averageLuminance = std::exp(*adaptedLogLuminance);
    r.exposure = static_cast<float>(tonemap::autoExposure(r.averageLuminance, settings.middleGray, settings.exposureCompensation()));
    return r;
}

ExposureReading ToneMapping::latestReading(ID3D11DeviceContext* context, const ToneMappingSettings& settings) {
    if (const auto value = readback_.poll(context)) latestLogLuminance_ = value;
    return reading(settings, latestLogLuminance_);
}

ExrAttributes ToneMapping::captureAttributes(ID3D11Device* device, ID3D11DeviceContext* context,
                                             const ToneMappingSettings& settings) const {
    std::optional<float> adapted;
    if (settings.autoExposure) {
        const ReadbackImage texel = readTexture2D(device, context, luminance_.adaptedLogLuminanceTexture());
        float value = 0.0f;
        std::memcpy(&value, texel.bytes.data(), sizeof(value));
        adapted = value;
    }
    const ExposureReading r = reading(settings, adapted);
    ExrAttributes a{
        {"firmament.toneMapping.operator", std::string(kToneMapOperatorNames[static_cast<size_t>(settings.op)])},
        {"firmament.toneMapping.exposure", r.exposure},
        {"firmament.toneMapping.exposureEv", std::log2(r.exposure)},
        {"firmament.toneMapping.autoExposure", settings.autoExposure ? 1 : 0},
        {"firmament.toneMapping.middleGray", settings.middleGray},
        {"firmament.toneMapping.whitePoint", settings.whitePoint},
        {"firmament.toneMapping.luminanceSaturation", settings.luminanceSaturation},
    };
    if (r.measured) a.emplace("firmament.toneMapping.averageLuminance", r.averageLuminance);
    if (settings.autoExposure)
        a.emplace("firmament.toneMapping.metering", std::string(kMeteringNames[static_cast<size_t>(settings.metering)]));
    return a;
}

}  // namespace firmament
