#include "clouds/CloudReference.h"

#include "clouds/CloudParticles.h"
#include "frame/FrameContext.h"
#include "gpu/CommonStates.h"
#include "tables/StagedComputation.h"

#include <algorithm>

namespace firmament {

namespace {
const ShaderKey kListShader{"clouds/reference_index.hlsl", "list_particles", "cs_5_0", {"LIST_PARTICLES=1"}};
const ShaderKey kMajorantShader{"clouds/reference_index.hlsl", "cell_majorants", "cs_5_0", {}};
const ShaderKey kCompositeVertexShader{"clouds/reference_composite.hlsl", "vs_main", "vs_5_0", {}};
const ShaderKey kCompositePixelShader{"clouds/reference_composite.hlsl", "ps_main", "ps_5_0", {}};
ShaderKey traceKey(int atmosphere) { return {"clouds/trace_clouds.hlsl", "main", "cs_5_0", {cloudAtmosphereDefine(atmosphere)}}; }
}  // namespace

std::string cloudAtmosphereDefine(int atmosphere) { return "CLOUD_ATMOSPHERE=" + std::to_string(atmosphere); }

CloudReference::CloudReference(ID3D11Device* device) : constants_(device), premultiplied_(states::premultipliedAlpha(device)) {}

void CloudReference::resize(ID3D11Device* device, const CloudSettings& settings) {
    const int width = settings.effectiveRingDimension() + 2, height = width * settings.rings;
    if (width == tableWidth_ && height == tableHeight_ && settings.maxLayers == layers_) return;
    tableWidth_ = width;
    tableHeight_ = height;
    layers_ = settings.maxLayers;
    counts_ = createColorTexture(device, width, height, DXGI_FORMAT_R32_UINT, D3D11_BIND_SHADER_RESOURCE | D3D11_BIND_UNORDERED_ACCESS);
    majorants_ = createStructuredBuffer(device, static_cast<unsigned>(width * height * 2 * layers_), 4, nullptr, "cloud reference's majorants");
    slots_ = createStructuredBuffer(device, static_cast<unsigned>(width * height * layers_), 4, nullptr, "cloud reference's cell slots");
}

void CloudReference::setConstants(ID3D11DeviceContext* context, const gpu::CloudReferenceConstants& constants) { constants_.update(context, constants); }

void CloudReference::buildIndex(FrameContext& frame, CloudParticles& particles, const CloudSettings& settings) {
    ID3D11DeviceContext* context = frame.context;
    auto pass = frame.profiler.scope("Clouds: reference index");
    resize(frame.device, settings);
    const UINT zero[4] = {};
    context->ClearUnorderedAccessViewUint(counts_.uav.Get(), zero);
    ID3D11Buffer* buffers[] = {frame.frameConstants, particles.fieldConstants()};
    context->CSSetConstantBuffers(0, 2, buffers);
    context->CSSetConstantBuffers(3, 1, constants_.address());
    // Each particle into its cell's list.
    bindCompute(context, frame.shaders.computeShader(kListShader), {nullptr, particles.particlesView(), nullptr, particles.argumentsView()},
                {counts_.uav.Get(), slots_.uav.Get()});
    context->DispatchIndirect(particles.particleArguments(), 0);
    unbindCompute(context, 4, 2);
    // Each cell's majorant from the lists around it.
    bindCompute(context, frame.shaders.computeShader(kMajorantShader),
                {nullptr, particles.particlesView(), nullptr, particles.argumentsView(), nullptr, nullptr, nullptr, nullptr, nullptr, nullptr,
                 counts_.srv.Get(), slots_.srv.Get()},
                {majorants_.uav.Get()});
    context->Dispatch(groupCount(static_cast<unsigned>(tableWidth_), 8), groupCount(static_cast<unsigned>(tableHeight_), 8), 1);
    unbindCompute(context, 12, 1);
}

void CloudReference::bindMedium(ID3D11DeviceContext* context, CloudParticles& particles) const {
    ID3D11ShaderResourceView* particleView = particles.particlesView();
    context->CSSetShaderResources(1, 1, &particleView);
    ID3D11ShaderResourceView* index[] = {counts_.srv.Get(), slots_.srv.Get(), majorants_.srv.Get()};
    context->CSSetShaderResources(10, 3, index);
    context->CSSetConstantBuffers(3, 1, constants_.address());
}

void CloudReference::trace(FrameContext& frame, CloudParticles& particles, const CloudSettings& settings, std::uint64_t key, int atmosphere,
                           glm::uvec4 modes) {
    ID3D11DeviceContext* context = frame.context;
    const int width = frame.width(), height = frame.height();
    if (accumulation_.width != width || accumulation_.height != height) {
        accumulation_ = createColorTexture(frame.device, width, height, DXGI_FORMAT_R32G32B32A32_FLOAT,
                                           D3D11_BIND_SHADER_RESOURCE | D3D11_BIND_UNORDERED_ACCESS);
        passes_ = 0;
    }
    const unsigned added = static_cast<unsigned>(std::clamp(settings.referencePaths, 1, 64));
    const unsigned stride = static_cast<unsigned>(std::clamp(settings.referenceStride, 1, 8));
    if (key != key_ || added != added_ || stride != stride_) passes_ = 0;
    key_ = key;
    added_ = added;
    stride_ = stride;
    // This pass's phase: the pixel of every stride x stride block it traces, in row order.
    const unsigned phase = passes_ % (stride * stride);
    gpu::CloudReferenceConstants c{};
    // The seed is the round's, so that a round at any stride draws the paths one pass at stride 1 would.
    const unsigned round = passes_ / (stride * stride);
    c.paths = glm::uvec4(passes_, added, round * 0x9e3779b9u + 0x632be5abu, 0u);
    c.options = glm::uvec4(static_cast<unsigned>(settings.particleDensity), 1u, kReferenceEventLimit, stride);
    c.modes = modes;
    c.target = glm::vec4(static_cast<float>(width), static_cast<float>(height), 1.0f / static_cast<float>(width), 1.0f / static_cast<float>(height));
    c.ground = glm::vec4(0.0f, kReferenceGroundAlbedo[0], kReferenceGroundAlbedo[1], kReferenceGroundAlbedo[2]);
    constants_.update(context, c);
    {
        auto pass = frame.profiler.scope("Clouds: reference paths");
        ID3D11Buffer* buffers[] = {frame.frameConstants, particles.fieldConstants()};
        context->CSSetConstantBuffers(0, 2, buffers);
        bindMedium(context, particles);
        ID3D11ShaderResourceView* depth = frame.targets.depth().srv.Get();
        context->CSSetShaderResources(3, 1, &depth);
        context->CSSetShader(frame.shaders.computeShader(traceKey(atmosphere)), nullptr, 0);
        context->CSSetUnorderedAccessViews(0, 1, accumulation_.uav.GetAddressOf(), nullptr);
        // A thread per pixel of this phase: the blocks along each side that reach past it.
        const unsigned across = (static_cast<unsigned>(width) - phase % stride + stride - 1) / stride;
        const unsigned down = (static_cast<unsigned>(height) - phase / stride + stride - 1) / stride;
        pathsLastPass_ = across * down * added;
        context->Dispatch(groupCount(across, 8), groupCount(down, 8), 1);
        ID3D11UnorderedAccessView* noView = nullptr;
        context->CSSetUnorderedAccessViews(0, 1, &noView, nullptr);
        ID3D11ShaderResourceView* none[13] = {};
        context->CSSetShaderResources(0, 13, none);
    }
    {
        auto pass = frame.profiler.scope("Clouds: reference mean");
        ID3D11RenderTargetView* hdr = frame.targets.hdr().rtv.Get();
        context->OMSetRenderTargets(1, &hdr, nullptr);
        context->OMSetBlendState(premultiplied_.Get(), nullptr, 0xffffffffu);
        context->OMSetDepthStencilState(nullptr, 0);
        const D3D11_VIEWPORT viewport{0.0f, 0.0f, static_cast<float>(width), static_cast<float>(height), 0.0f, 1.0f};
        context->RSSetViewports(1, &viewport);
        context->IASetPrimitiveTopology(D3D11_PRIMITIVE_TOPOLOGY_TRIANGLELIST);
        context->IASetInputLayout(nullptr);
        context->VSSetShader(frame.shaders.vertexShader(kCompositeVertexShader), nullptr, 0);
        context->PSSetShader(frame.shaders.pixelShader(kCompositePixelShader), nullptr, 0);
        context->PSSetConstantBuffers(3, 1, constants_.address());
        context->PSSetShaderResources(0, 1, accumulation_.srv.GetAddressOf());
        context->Draw(3, 0);
        ID3D11ShaderResourceView* none = nullptr;
        context->PSSetShaderResources(0, 1, &none);
        context->OMSetBlendState(nullptr, nullptr, 0xffffffffu);
    }
    ++passes_;
}

unsigned CloudReference::pathsPerPixel() const { return passes_ / (stride_ * stride_) * added_; }

}  // namespace firmament
