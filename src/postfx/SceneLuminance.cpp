#include "postfx/SceneLuminance.h"

#include "gpu/Hresult.h"

#include <algorithm>

namespace firmament {

namespace {
const ShaderKey kLogLuminanceVs{"postfx/log_luminance.hlsl", "vs_main", "vs_5_0", {}};
const ShaderKey kLogLuminancePs{"postfx/log_luminance.hlsl", "ps_main", "ps_5_0", {}};
const ShaderKey kDownsampleVs{"postfx/average_downsample.hlsl", "vs_main", "vs_5_0", {}};
const ShaderKey kDownsamplePs{"postfx/average_downsample.hlsl", "ps_main", "ps_5_0", {}};
const ShaderKey kAdaptationVs{"postfx/light_adaptation.hlsl", "vs_main", "vs_5_0", {}};
const ShaderKey kAdaptationPs{"postfx/light_adaptation.hlsl", "ps_main", "ps_5_0", {}};
const ShaderKey kHistogramCs{"postfx/luminance_histogram.hlsl", "main", "cs_5_0", {}};
constexpr DXGI_FORMAT kFormat = DXGI_FORMAT_R32_FLOAT;  // log values: float keeps the mean exact enough
}  // namespace

SceneLuminance::SceneLuminance(ID3D11Device* device) : fullscreen_(device), constants_(device) {
    D3D11_TEXTURE2D_DESC desc{};
    desc.Width = desc.Height = kSize;
    desc.MipLevels = kMipLevels;
    desc.ArraySize = 1;
    desc.Format = kFormat;
    desc.SampleDesc.Count = 1;
    desc.Usage = D3D11_USAGE_DEFAULT;
    desc.BindFlags = D3D11_BIND_RENDER_TARGET | D3D11_BIND_SHADER_RESOURCE;
    check(device->CreateTexture2D(&desc, nullptr, &logLuminance_), "CreateTexture2D (log luminance)");
    for (UINT level = 0; level < kMipLevels; ++level) {
        D3D11_SHADER_RESOURCE_VIEW_DESC srv{};
        srv.Format = kFormat;
        srv.ViewDimension = D3D11_SRV_DIMENSION_TEXTURE2D;
        srv.Texture2D.MostDetailedMip = level;
        srv.Texture2D.MipLevels = 1;
        check(device->CreateShaderResourceView(logLuminance_.Get(), &srv, &levelViews_[level]), "CreateShaderResourceView (log luminance level)");
        D3D11_RENDER_TARGET_VIEW_DESC rtv{};
        rtv.Format = kFormat;
        rtv.ViewDimension = D3D11_RTV_DIMENSION_TEXTURE2D;
        rtv.Texture2D.MipSlice = level;
        check(device->CreateRenderTargetView(logLuminance_.Get(), &rtv, &levelTargets_[level]), "CreateRenderTargetView (log luminance level)");
    }
    histogram_ = createColorTexture(device, 1, 1, kFormat, D3D11_BIND_UNORDERED_ACCESS | D3D11_BIND_SHADER_RESOURCE);
    metered_ = createColorTexture(device, 1, 1, kFormat, D3D11_BIND_SHADER_RESOURCE);
    for (Texture2D& adapted : adapted_)
        adapted = createColorTexture(device, 1, 1, kFormat, D3D11_BIND_RENDER_TARGET | D3D11_BIND_SHADER_RESOURCE);
}

void SceneLuminance::measure(ID3D11DeviceContext* context, ShaderLibrary& shaders, ID3D11ShaderResourceView* hdrFrame,
                             int width, int height, const ToneMappingSettings& settings) {
    gpu::SceneLuminanceConstants constants{};
    constants.source = glm::vec4(static_cast<float>(width), static_cast<float>(height), 0.0f, 0.0f);
    constants.histogram = glm::vec4(settings.histogramLow, std::max(settings.histogramHigh, settings.histogramLow), 0.0f, 0.0f);
    constants_.update(context, constants);

    fullscreen_.bindTarget(context, levelTargets_[0].Get(), kSize, kSize);
    context->PSSetConstantBuffers(0, 1, constants_.address());
    context->PSSetShaderResources(0, 1, &hdrFrame);
    fullscreen_.draw(context, shaders, kLogLuminanceVs, kLogLuminancePs);

    ID3D11ShaderResourceView* none = nullptr;
    context->PSSetShaderResources(0, 1, &none);
    if (settings.metering == Metering::Histogram) {
        context->OMSetRenderTargets(0, nullptr, nullptr);
        context->CSSetConstantBuffers(0, 1, constants_.address());
        context->CSSetShaderResources(0, 1, levelViews_[0].GetAddressOf());
        context->CSSetUnorderedAccessViews(0, 1, histogram_.uav.GetAddressOf(), nullptr);
        context->CSSetShader(shaders.computeShader(kHistogramCs), nullptr, 0);
        context->Dispatch(1, 1, 1);
        ID3D11UnorderedAccessView* noView = nullptr;
        context->CSSetUnorderedAccessViews(0, 1, &noView, nullptr);
        context->CSSetShaderResources(0, 1, &none);
        context->CopyResource(metered_.texture.Get(), histogram_.texture.Get());
        return;
    }
    for (int level = 1; level < kMipLevels; ++level) {
        fullscreen_.bindTarget(context, levelTargets_[level].Get(), kSize >> level, kSize >> level);
        context->PSSetShaderResources(0, 1, levelViews_[level - 1].GetAddressOf());
        fullscreen_.draw(context, shaders, kDownsampleVs, kDownsamplePs);
    }
    context->PSSetShaderResources(0, 1, &none);
    context->CopySubresourceRegion(metered_.texture.Get(), 0, 0, 0, 0, logLuminance_.Get(), kMipLevels - 1, nullptr);
}

void SceneLuminance::adapt(ID3D11DeviceContext* context, ShaderLibrary& shaders, float weight) {
    const Texture2D& previous = adapted_[current_];
    current_ = 1 - current_;
    gpu::SceneLuminanceConstants constants{};
    constants.adaptation.x = reset_ ? 1.0f : weight;
    reset_ = false;
    constants_.update(context, constants);

    fullscreen_.bindTarget(context, adapted_[current_].rtv.Get(), 1, 1);
    context->PSSetConstantBuffers(0, 1, constants_.address());
    ID3D11ShaderResourceView* inputs[2] = {metered_.srv.Get(), previous.srv.Get()};
    context->PSSetShaderResources(0, 2, inputs);
    fullscreen_.draw(context, shaders, kAdaptationVs, kAdaptationPs);
    ID3D11ShaderResourceView* none[2] = {nullptr, nullptr};
    context->PSSetShaderResources(0, 2, none);
}

}  // namespace firmament
