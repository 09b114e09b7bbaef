#include "frame/FrameTargets.h"

#include "gpu/SwapChain.h"

namespace firmament {

void FrameTargets::resize(ID3D11Device* device, int width, int height, bool withOutput, HdrPrecision precision) {
    const DXGI_FORMAT radiance = precision == HdrPrecision::Float32 ? DXGI_FORMAT_R32G32B32A32_FLOAT : DXGI_FORMAT_R16G16B16A16_FLOAT;
    hdr_ = createColorTexture(device, width, height, radiance, D3D11_BIND_RENDER_TARGET | D3D11_BIND_SHADER_RESOURCE | D3D11_BIND_UNORDERED_ACCESS);
    depth_ = createDepthTexture(device, width, height);
    sceneCopy_ = createColorTexture(device, width, height, radiance, D3D11_BIND_SHADER_RESOURCE);
    output_ = withOutput ? createColorTexture(device, width, height, SwapChain::kFormat, D3D11_BIND_RENDER_TARGET) : Texture2D{};
    width_ = width;
    height_ = height;
    precision_ = precision;
}

const Texture2D& FrameTargets::copyHdr(ID3D11DeviceContext* context) {
    context->CopyResource(sceneCopy_.texture.Get(), hdr_.texture.Get());
    return sceneCopy_;
}

}  // namespace firmament
