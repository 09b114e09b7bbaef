#include "clouds/VolumeBlendingPass.h"

#include "gpu/CommonStates.h"
#include "gpu/ShaderLibrary.h"

#include <algorithm>

namespace firmament {

namespace {
const ShaderKey kResolveVertexShader{"clouds/resolve_fragments.hlsl", "vs_main", "vs_5_0", {}};
const ShaderKey kResolveListsShader{"clouds/resolve_fragments.hlsl", "ps_main", "ps_5_0", {}};
const ShaderKey kResolveOrderedShader{"clouds/resolve_ordered.hlsl", "ps_main", "ps_5_0", {}};
constexpr unsigned kNodeStride = 28;  // FragmentNode in fragment_lists.hlsli
}  // namespace

BlendingSupport queryBlendingSupport(ID3D11Device* device) {
    D3D11_FEATURE_DATA_D3D11_OPTIONS2 options{};
    BlendingSupport support;
    if (SUCCEEDED(device->CheckFeatureSupport(D3D11_FEATURE_D3D11_OPTIONS2, &options, sizeof(options)))) {
        support.rasterizerOrderedViews = options.ROVsSupported != FALSE;
        support.typedUavLoads = options.TypedUAVLoadAdditionalFormats != FALSE;
    }
    return support;
}

VolumeBlendingPass::VolumeBlendingPass(ID3D11Device* device)
    : lists_(device, kNodeStride, kMaxPoolBytes, "cloud fragment nodes"),
      resolveConstants_(device),
      premultiplied_(states::premultipliedAlpha(device)),
      noColourWrites_(states::noColourWrites(device)),
      noCulling_(states::cullNone(device)),
      noDepth_(states::depthNone(device)) {}

void VolumeBlendingPass::begin(ID3D11Device* device, ID3D11DeviceContext* context, ParticleBlending path, int width, int height) {
    path_ = path;
    if (path == ParticleBlending::Alpha) return;
    const bool resized = width != width_ || height != height_;
    width_ = width;
    height_ = height;
    if (path == ParticleBlending::PerPixelLists) {
        const size_t room = size_t{static_cast<unsigned>(width)} * static_cast<unsigned>(height) * kNodesPerPixel;
        lists_.resize(device, width, height, static_cast<unsigned>(std::min<size_t>(room, kInitialPoolBytes / kNodeStride)));
        lists_.clear(device, context);
    } else {
        if (resized || !storedColour_.texture) {
            const UINT bind = D3D11_BIND_SHADER_RESOURCE | D3D11_BIND_UNORDERED_ACCESS;
            storedColour_ = createColorTexture(device, width, height, DXGI_FORMAT_R32G32B32A32_FLOAT, bind);
            storedExtent_ = createColorTexture(device, width, height, DXGI_FORMAT_R32G32_FLOAT, bind);
        }
        const float zero[4] = {};
        context->ClearUnorderedAccessViewFloat(storedColour_.uav.Get(), zero);
        context->ClearUnorderedAccessViewFloat(storedExtent_.uav.Get(), zero);
    }
}

void VolumeBlendingPass::bindForParticles(ID3D11DeviceContext* context, ID3D11RenderTargetView* target, ID3D11BlendState* blend) const {
    if (path_ == ParticleBlending::PerPixelLists) {
        // The lists' pixel shader writes no colour; the target stays bound, unwritten.
        ID3D11UnorderedAccessView* views[] = {lists_.heads().uav.Get(), lists_.nodes().uav.Get()};
        context->OMSetRenderTargetsAndUnorderedAccessViews(1, &target, nullptr, 1, 2, views, nullptr);
        context->OMSetBlendState(noColourWrites_.Get(), nullptr, 0xffffffffu);
        return;
    }
    if (path_ == ParticleBlending::RasterizerOrdered) {
        ID3D11UnorderedAccessView* views[] = {storedColour_.uav.Get(), storedExtent_.uav.Get()};
        context->OMSetRenderTargetsAndUnorderedAccessViews(1, &target, nullptr, 1, 2, views, nullptr);
    } else {
        context->OMSetRenderTargets(1, &target, nullptr);
    }
    context->OMSetBlendState(blend ? blend : premultiplied_.Get(), nullptr, 0xffffffffu);
}

void VolumeBlendingPass::bindListsForCompute(ID3D11DeviceContext* context) const {
    ID3D11UnorderedAccessView* views[] = {lists_.heads().uav.Get(), lists_.nodes().uav.Get()};
    context->CSSetUnorderedAccessViews(1, 2, views, nullptr);
}

void VolumeBlendingPass::resolve(ID3D11DeviceContext* context, ShaderLibrary& shaders, ID3D11RenderTargetView* target, ID3D11BlendState* blend) {
    if (path_ == ParticleBlending::Alpha) return;
    const D3D11_VIEWPORT viewport{0.0f, 0.0f, static_cast<float>(width_), static_cast<float>(height_), 0.0f, 1.0f};
    context->RSSetViewports(1, &viewport);
    context->RSSetState(noCulling_.Get());
    context->OMSetDepthStencilState(noDepth_.Get(), 0);
    context->OMSetBlendState(blend ? blend : premultiplied_.Get(), nullptr, 0xffffffffu);
    context->IASetInputLayout(nullptr);
    context->IASetPrimitiveTopology(D3D11_PRIMITIVE_TOPOLOGY_TRIANGLELIST);
    context->VSSetShader(shaders.vertexShader(kResolveVertexShader), nullptr, 0);
    if (path_ == ParticleBlending::PerPixelLists) {
        ID3D11UnorderedAccessView* views[] = {lists_.heads().uav.Get()};
        context->OMSetRenderTargetsAndUnorderedAccessViews(1, &target, nullptr, 1, 1, views, nullptr);
        context->PSSetShaderResources(0, 1, lists_.nodes().srv.GetAddressOf());
        resolveConstants_.update(context, glm::uvec4(static_cast<unsigned>(height_), 0u, 0u, 0u));
        ID3D11Buffer* constants[] = {resolveConstants_.get()};
        context->PSSetConstantBuffers(0, 1, constants);
        context->PSSetShader(shaders.pixelShader(kResolveListsShader), nullptr, 0);
        context->Draw(3, 0);
        ID3D11ShaderResourceView* none[1] = {};
        context->PSSetShaderResources(0, 1, none);
        lists_.copyCounts(context);
    } else {
        ID3D11UnorderedAccessView* views[] = {storedColour_.uav.Get(), storedExtent_.uav.Get()};
        context->OMSetRenderTargetsAndUnorderedAccessViews(1, &target, nullptr, 1, 2, views, nullptr);
        context->PSSetShader(shaders.pixelShader(kResolveOrderedShader), nullptr, 0);
        context->Draw(3, 0);
    }
    context->OMSetRenderTargets(1, &target, nullptr);  // unbinds the views
    context->OMSetBlendState(nullptr, nullptr, 0xffffffffu);
}

VolumeBlendingPass::Overflow VolumeBlendingPass::readOverflow(ID3D11Device* device, ID3D11DeviceContext* context) const {
    if (path_ != ParticleBlending::PerPixelLists) return {};
    const GpuLinkedLists::Counts c = lists_.read(device, context);
    return {c.asked, c.dropped, c.second};
}

std::optional<VolumeBlendingPass::Overflow> VolumeBlendingPass::latestOverflow() const {
    const std::optional<GpuLinkedLists::Counts> c = lists_.latest();
    if (!c) return std::nullopt;
    return Overflow{c->asked, c->dropped, c->second};
}

size_t VolumeBlendingPass::memoryBytes() const {
    const size_t pixels = static_cast<size_t>(width_) * static_cast<size_t>(height_);
    switch (path_) {
        case ParticleBlending::PerPixelLists: return lists_.bytes();
        case ParticleBlending::RasterizerOrdered: return pixels * (16 + 8);
        case ParticleBlending::Alpha: break;
    }
    return 0;
}

}  // namespace firmament
