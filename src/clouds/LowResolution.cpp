#include "clouds/LowResolution.h"

#include "gpu/CommonStates.h"
#include "gpu/ShaderLibrary.h"

namespace firmament {

namespace {
const ShaderKey kDownsampleVertexShader{"clouds/downsample_depth.hlsl", "vs_main", "vs_5_0", {}};
const ShaderKey kDownsamplePixelShader{"clouds/downsample_depth.hlsl", "ps_main", "ps_5_0", {}};
const ShaderKey kUpsampleVertexShader{"clouds/upsample_clouds.hlsl", "vs_main", "vs_5_0", {}};
const ShaderKey kUpsamplePixelShader{"clouds/upsample_clouds.hlsl", "ps_main", "ps_5_0", {}};

}  // namespace

CloudLowResolution::CloudLowResolution(ID3D11Device* device)
    : fullscreen_(device), constants_(device), transmittance_(states::premultipliedAlphaTransmittance(device)), premultiplied_(states::premultipliedAlpha(device)) {}

void CloudLowResolution::begin(ID3D11Device* device, ID3D11DeviceContext* context, ShaderLibrary& shaders, ID3D11ShaderResourceView* sceneDepth,
                               int width, int height, int factor) {
    const int w = lowSize(width, factor), h = lowSize(height, factor);
    if (clouds_.width != w || clouds_.height != h) {
        const UINT bind = D3D11_BIND_RENDER_TARGET | D3D11_BIND_SHADER_RESOURCE;
        clouds_ = createColorTexture(device, w, h, DXGI_FORMAT_R16G16B16A16_FLOAT, bind);
        depth_ = createColorTexture(device, w, h, DXGI_FORMAT_R32_FLOAT, bind);
    }
    factor_ = factor;
    constants_.update(context, gpu::CloudUpsampleConstants{glm::uvec4(static_cast<unsigned>(factor), static_cast<unsigned>(w), static_cast<unsigned>(h), 0u)});
    fullscreen_.bindTarget(context, depth_.rtv.Get(), w, h);
    fullscreen_.draw(context, shaders, kDownsampleVertexShader, kDownsamplePixelShader, {constants_.get()}, {sceneDepth}, nullptr);
    const float empty[4] = {0.0f, 0.0f, 0.0f, 1.0f};
    context->ClearRenderTargetView(clouds_.rtv.Get(), empty);
}

void CloudLowResolution::upsample(ID3D11DeviceContext* context, ShaderLibrary& shaders, ID3D11ShaderResourceView* sceneDepth,
                                  ID3D11RenderTargetView* target, int width, int height) {
    fullscreen_.bindTarget(context, target, width, height);
    context->OMSetBlendState(premultiplied_.Get(), nullptr, 0xffffffffu);
    fullscreen_.draw(context, shaders, kUpsampleVertexShader, kUpsamplePixelShader, {constants_.get()}, {clouds_.srv.Get(), depth_.srv.Get(), sceneDepth},
                     nullptr);
    context->OMSetBlendState(nullptr, nullptr, 0xffffffffu);
}

}  // namespace firmament
