#include "clouds/CloudParticles.h"

#include "clouds/CloudField.h"
#include "clouds/CloudGrid.h"
#include "core/Camera.h"
#include "frame/FrameContext.h"
#include "gpu/CommonStates.h"
#include "tables/StagedComputation.h"

#include <vector>

namespace firmament {

namespace {
ShaderKey computeKey(const char* file, const char* entry = "main") { return {std::string("clouds/") + file + ".hlsl", entry, "cs_5_0", {}}; }
const ShaderKey kShapeVertexShader{"clouds/bounding_shapes.hlsl", "vs_main", "vs_5_0", {}};
const ShaderKey kShapePixelShader{"clouds/bounding_shapes.hlsl", "ps_main", "ps_5_0", {}};
constexpr unsigned kSortBlock = 256;

}  // namespace

CloudParticles::CloudParticles(ID3D11Device* device)
    : fieldBuffer_(device),
      sortBuffer_(device),
      noCulling_(states::cullNone(device)),
      depth_(states::depthReversed(device)),
      arguments_(createIndirectArguments(device, "cloud particle arguments")),
      visibleArguments_(createIndirectArguments(device, "cloud visible particle arguments")) {}

void CloudParticles::resizeGrid(ID3D11Device* device, const CloudSettings& settings) {
    const int dimension = settings.effectiveRingDimension();
    if (settings.rings == rings_ && dimension == dimension_ && settings.maxLayers == layers_) return;
    const CloudGrid grid(settings);
    std::vector<std::uint32_t> packed;
    for (const CloudCell& cell : grid.cells()) packed.push_back(packCloudCell(cell));
    cells_ = createStructuredBuffer(device, static_cast<unsigned>(packed.size()), sizeof(std::uint32_t), packed.data(), "cloud cells");
    validCells_ = std::make_unique<WorkList>(device, static_cast<unsigned>(packed.size()));
    capacity_ = cloudParticleCapacity(settings);
    particles_ = createStructuredBuffer(device, capacity_, sizeof(gpu::CloudParticle), nullptr, "cloud particles");
    for (StructuredBuffer& keys : keys_) keys = createStructuredBuffer(device, capacity_, 2 * sizeof(std::uint32_t), nullptr, "cloud sort keys");
    visibleKeys_ = createStructuredBuffer(device, capacity_, 2 * sizeof(std::uint32_t), nullptr, "cloud visible keys");
    rings_ = settings.rings;
    dimension_ = dimension;
    layers_ = settings.maxLayers;
}

void CloudParticles::generateDensityMap(FrameContext& frame, int resolution) {
    if (resolution == resolution_) return;
    densityMap_ = createColorTexture(frame.device, resolution, resolution, DXGI_FORMAT_R32_FLOAT,
                                     D3D11_BIND_SHADER_RESOURCE | D3D11_BIND_UNORDERED_ACCESS);
    auto pass = frame.profiler.scope("Clouds: density map");
    ID3D11Buffer* buffers[] = {frame.frameConstants, fieldBuffer_.get()};
    frame.context->CSSetConstantBuffers(0, 2, buffers);
    bindCompute(frame.context, frame.shaders.computeShader(computeKey("density_map")), {}, {densityMap_.uav.Get()});
    const unsigned groups = groupCount(static_cast<unsigned>(resolution), 8);
    frame.context->Dispatch(groups, groups, 1);
    unbindCompute(frame.context, 0, 1);
    resolution_ = resolution;
}

void CloudParticles::update(FrameContext& frame, const CloudSettings& settings, glm::vec4 tableSizes) {
    ID3D11DeviceContext* context = frame.context;
    resizeGrid(frame.device, settings);
    constants_ = cloudFieldConstants(settings, glm::dvec3(frame.camera.position), frame.timeSeconds);
    constants_.tableSizes = tableSizes;
    fieldBuffer_.update(context, constants_);
    generateDensityMap(frame, settings.densityResolution);
    ID3D11Buffer* buffers[] = {frame.frameConstants, fieldBuffer_.get(), sortBuffer_.get()};
    context->CSSetConstantBuffers(0, 3, buffers);
    {
        auto pass = frame.profiler.scope("Clouds: valid cells");
        validCells_->clear(context);
        bindCompute(context, frame.shaders.computeShader(computeKey("valid_cells")), {cells_.srv.Get(), densityMap_.srv.Get()},
                    {validCells_->itemsUav(), validCells_->argumentsUav()});
        context->Dispatch(groupCount(constants_.layout.w, 64), 1, 1);
        unbindCompute(context, 2, 2);
        bindCompute(context, frame.shaders.computeShader(computeKey("list_arguments", "cells")), {}, {validCells_->argumentsUav()});
        context->Dispatch(1, 1, 1);
        unbindCompute(context, 0, 1);
    }
    {
        auto pass = frame.profiler.scope("Clouds: particle generation");
        const UINT zero[4] = {0, 0, 0, 0};
        context->ClearUnorderedAccessViewUint(arguments_.uav.Get(), zero);
        bindCompute(context, frame.shaders.computeShader(computeKey("generate_particles")),
                    {cells_.srv.Get(), densityMap_.srv.Get(), validCells_->itemsSrv(), validCells_->argumentsSrv()},
                    {particles_.uav.Get(), keys_[0].uav.Get(), arguments_.uav.Get()});
        validCells_->dispatch(context);
        unbindCompute(context, 4, 3);
        bindCompute(context, frame.shaders.computeShader(computeKey("list_arguments", "particles")), {}, {arguments_.uav.Get()});
        context->Dispatch(1, 1, 1);
        unbindCompute(context, 0, 1);
    }
    sort(frame);
    culled_ = settings.visibilityCulling;
    if (culled_) cullToView(frame);
}

// One group over the sorted keys (clouds/cull_particles.hlsl): the visible ones, in order.
void CloudParticles::cullToView(FrameContext& frame) {
    ID3D11DeviceContext* context = frame.context;
    auto pass = frame.profiler.scope("Clouds: visibility");
    ID3D11Buffer* buffers[] = {frame.frameConstants, fieldBuffer_.get()};
    context->CSSetConstantBuffers(0, 2, buffers);
    bindCompute(context, frame.shaders.computeShader(computeKey("cull_particles")), {arguments_.srv.Get(), keys_[sortedIndex_].srv.Get(), particles_.srv.Get()},
                {visibleKeys_.uav.Get(), visibleArguments_.uav.Get()});
    context->Dispatch(1, 1, 1);
    unbindCompute(context, 3, 2);
}

// Blocks of 256 sorted in place in keys_[0]; then runs of 256, 512, ... merged in pairs from one
// buffer into the other until a run holds the capacity.
void CloudParticles::sort(FrameContext& frame) {
    ID3D11DeviceContext* context = frame.context;
    auto pass = frame.profiler.scope("Clouds: sort");
    bindCompute(context, frame.shaders.computeShader(computeKey("sort_blocks")), {arguments_.srv.Get()}, {keys_[0].uav.Get()});
    context->DispatchIndirect(arguments_.buffer.Get(), 0);
    unbindCompute(context, 1, 1);
    int source = 0;
    for (unsigned run = kSortBlock; run < capacity_; run *= 2) {
        sortBuffer_.update(context, gpu::CloudSortConstants{glm::uvec4(run, 0u, 0u, 0u)});
        bindCompute(context, frame.shaders.computeShader(computeKey("merge_sorted")), {arguments_.srv.Get(), keys_[source].srv.Get()},
                    {keys_[1 - source].uav.Get()});
        context->DispatchIndirect(arguments_.buffer.Get(), 0);
        unbindCompute(context, 2, 1);
        source = 1 - source;
    }
    sortedIndex_ = source;
}

void CloudParticles::drawBoundingShapes(FrameContext& frame) {
    ID3D11DeviceContext* context = frame.context;
    auto pass = frame.profiler.scope("Clouds: particles' bounding shapes");
    ID3D11RenderTargetView* hdr = frame.targets.hdr().rtv.Get();
    context->OMSetRenderTargets(1, &hdr, frame.targets.depth().dsv.Get());
    context->OMSetDepthStencilState(depth_.Get(), 0);
    context->OMSetBlendState(nullptr, nullptr, 0xffffffffu);
    context->RSSetState(noCulling_.Get());
    drawInstanced(frame, kShapeVertexShader, kShapePixelShader, ParticleSet::InView);
    context->OMSetDepthStencilState(nullptr, 0);
}

void CloudParticles::drawInstanced(FrameContext& frame, const ShaderKey& vertexShader, const ShaderKey& pixelShader, ParticleSet set, int width, int height) {
    const bool inView = set == ParticleSet::InView && culled_;
    ID3D11DeviceContext* context = frame.context;
    const D3D11_VIEWPORT viewport{0.0f, 0.0f, static_cast<float>(width > 0 ? width : frame.width()), static_cast<float>(height > 0 ? height : frame.height()),
                                  0.0f, 1.0f};
    context->RSSetViewports(1, &viewport);
    context->IASetInputLayout(nullptr);
    context->IASetPrimitiveTopology(D3D11_PRIMITIVE_TOPOLOGY_TRIANGLESTRIP);
    ID3D11Buffer* buffers[] = {frame.frameConstants, fieldBuffer_.get()};
    context->VSSetConstantBuffers(0, 2, buffers);
    context->PSSetConstantBuffers(0, 2, buffers);
    ID3D11ShaderResourceView* inputs[] = {inView ? visibleKeys_.srv.Get() : keys_[sortedIndex_].srv.Get(), particles_.srv.Get()};
    context->VSSetShaderResources(0, 2, inputs);
    context->PSSetShaderResources(0, 2, inputs);
    context->VSSetShader(frame.shaders.vertexShader(vertexShader), nullptr, 0);
    context->PSSetShader(frame.shaders.pixelShader(pixelShader), nullptr, 0);
    context->DrawInstancedIndirect(inView ? visibleArguments_.buffer.Get() : arguments_.buffer.Get(), 4 * sizeof(unsigned));
    ID3D11ShaderResourceView* none[2] = {};
    context->VSSetShaderResources(0, 2, none);
    context->PSSetShaderResources(0, 2, none);
    context->RSSetState(nullptr);
}

}  // namespace firmament
