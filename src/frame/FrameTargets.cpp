#include "frame/FrameTargets.h"

#include "gpu/SwapChain.h"

namespace firmament {

void FrameTargets::resize(ID3D11Device* device, int width, int height, bool withOutput) {
    hdr_ = createColorTexture(device, width, height, DXGI_FORMAT_R16G16B16A16_FLOAT,
                              D3D11_BIND_RENDER_TARGET | D3D11_BIND_SHADER_RESOURCE | D3D11_BIND_UNORDERED_ACCESS);
    depth_ = createDepthTexture(device, width, height);
    sceneCopy_ = createColorTexture(device, width, height, DXGI_FORMAT_R16G16B16A16_FLOAT, D3D11_BIND_SHADER_RESOURCE);
    output_ = withOutput ? createColorTexture(device, width, height, SwapChain::kFormat, D3D11_BIND_RENDER_TARGET) : Texture2D{};
    width_ = width;
    height_ = height;
}

const Texture2D& FrameTargets::copyHdr(ID3D11DeviceContext* context) {
    context->CopyResource(sceneCopy_.texture.Get(), hdr_.texture.Get());
    return sceneCopy_;
}

}  // namespace firmament
