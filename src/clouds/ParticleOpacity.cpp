#include "clouds/ParticleOpacity.h"

#include "clouds/CloudParticles.h"
#include "clouds/LightSpace.h"
#include "clouds/ParticleTables.h"
#include "frame/FrameContext.h"
#include "gpu/CommonStates.h"
#include "tables/StagedComputation.h"

#include <algorithm>

namespace firmament {

namespace {
const ShaderKey kTileVertexShader{"clouds/tile_particles.hlsl", "vs_main", "vs_5_0", {}};
const ShaderKey kTilePixelShader{"clouds/tile_particles.hlsl", "ps_main", "ps_5_0", {}};
const ShaderKey kOrderShader{"clouds/order_tiles.hlsl", "main", "cs_5_0", {}};
const ShaderKey kOpacityShader{"clouds/particle_opacity.hlsl", "main", "cs_5_0", {}};
constexpr unsigned kNodeStride = 12;  // uint3: slot, next, the distance toward the sun
}  // namespace

ParticleOpacity::ParticleOpacity(ID3D11Device* device)
    : constantsBuffer_(device),
      noColourWrites_(states::noColourWrites(device)),
      noCulling_(states::cullNone(device)),
      linearWrap_(states::linearWrap(device)),
      tiles_(device, kNodeStride, kMaxPoolBytes, "light-space tile nodes") {}

void ParticleOpacity::resize(ID3D11Device* device, unsigned particleCapacity, int resolution) {
    if (resolution != resolution_) {
        resolution_ = resolution;
        rasterTarget_ = createColorTexture(device, resolution, resolution, DXGI_FORMAT_R8_UNORM, D3D11_BIND_RENDER_TARGET);
    }
    if (particleCapacity != particleCapacity_) {
        particleCapacity_ = particleCapacity;
        column_ = createStructuredBuffer(device, std::max(particleCapacity, 1u), sizeof(float) * 4, nullptr, "cloud particles' columns along the sun");
    }
    // A particle covers about (its footprint / the tile)^2 tiles: 4x as many per doubling.
    const size_t perParticle = size_t{kNodesPerParticle} * static_cast<size_t>(resolution / 512 > 1 ? (resolution / 512) * (resolution / 512) : 1);
    tiles_.resize(device, resolution, resolution, static_cast<unsigned>(std::min<size_t>(size_t{particleCapacity} * perParticle, kMaxPoolBytes / kNodeStride)));
}

// The particles drawn over the light-space map into each tile's list, each list ordered from the sun.
void ParticleOpacity::buildTiles(FrameContext& frame, CloudParticles& particles, const CloudSettings& settings) {
    ID3D11DeviceContext* context = frame.context;
    tiles_.clear(frame.device, context);  // after growing the pool, whose capacity the constants carry
    const glm::vec4 camera = frame.constants.cameraPosition, sun = frame.constants.directionToSun;
    constants_ = lightSpaceConstants(settings, glm::dvec3(camera.x, camera.y, camera.z), glm::dvec3(sun.x, sun.y, sun.z), tiles_.capacity());
    constantsBuffer_.update(context, constants_);
    const unsigned n = static_cast<unsigned>(resolution_);
    auto pass = frame.profiler.scope("Clouds: light-space tiling");
    // Rasterized over the map with no colour written: the pixel shader appends to the lists.
    ID3D11RenderTargetView* target = rasterTarget_.rtv.Get();
    ID3D11UnorderedAccessView* views[] = {tiles_.heads().uav.Get(), tiles_.nodes().uav.Get()};
    context->OMSetRenderTargetsAndUnorderedAccessViews(1, &target, nullptr, 1, 2, views, nullptr);
    context->OMSetBlendState(noColourWrites_.Get(), nullptr, 0xffffffffu);
    context->OMSetDepthStencilState(nullptr, 0);
    context->RSSetState(noCulling_.Get());
    ID3D11Buffer* lightSpace = constantsBuffer_.get();
    context->VSSetConstantBuffers(2, 1, &lightSpace);
    context->PSSetConstantBuffers(2, 1, &lightSpace);
    particles.drawInstanced(frame, kTileVertexShader, kTilePixelShader, ParticleSet::All, resolution_, resolution_);
    context->OMSetRenderTargets(0, nullptr, nullptr);
    context->OMSetBlendState(nullptr, nullptr, 0xffffffffu);
    // Each tile's list ordered from the sun.
    ID3D11Buffer* buffers[] = {frame.frameConstants, particles.fieldConstants(), lightSpace};
    context->CSSetConstantBuffers(0, 3, buffers);
    bindCompute(context, frame.shaders.computeShader(kOrderShader), {}, {tiles_.heads().uav.Get(), tiles_.nodes().uav.Get()});
    context->Dispatch(groupCount(n, 8), groupCount(n, 8), 1);
    unbindCompute(context, 0, 2);
    tiles_.copyCounts(context);
}

void ParticleOpacity::compute(FrameContext& frame, CloudParticles& particles, const ParticleTables& tables, const CloudSettings& settings) {
    ID3D11DeviceContext* context = frame.context;
    computed_ = true;
    resize(frame.device, particles.capacity(), settings.lightSpaceResolution);
    // The first lists of a new pool that did not fit it are built again, into a larger one.
    do buildTiles(frame, particles, settings);
    while (tiles_.firstBuildOverflowed(frame.device, context));
    {
        auto pass = frame.profiler.scope("Clouds: particle opacity");
        bindCompute(context, frame.shaders.computeShader(kOpacityShader),
                    {particles.sortedKeysView(), particles.particlesView(), tables.opticalDepth.srv.Get(), particles.argumentsView(), tiles_.heads().srv.Get(),
                     tiles_.nodes().srv.Get()},
                    {column_.uav.Get()});
        context->CSSetSamplers(0, 1, linearWrap_.GetAddressOf());
        context->DispatchIndirect(particles.particleArguments(), 0);
        unbindCompute(context, 6, 1);
    }
}

void ParticleOpacity::clear(ID3D11Device* device, ID3D11DeviceContext* context, unsigned particleCapacity) {
    resize(device, particleCapacity, resolution_ > 0 ? resolution_ : 256);
    computed_ = false;
    const UINT zero[4] = {0u, 0u, 0u, 0u};
    context->ClearUnorderedAccessViewUint(column_.uav.Get(), zero);
}

ParticleOpacity::Counts ParticleOpacity::readCounts(ID3D11Device* device, ID3D11DeviceContext* context) const {
    const GpuLinkedLists::Counts c = tiles_.read(device, context);
    return {c.asked, c.dropped};
}

}  // namespace firmament
