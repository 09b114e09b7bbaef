#include "clouds/ParticleOpacity.h"

#include "clouds/CloudParticles.h"
#include "clouds/LightSpace.h"
#include "clouds/ParticleTables.h"
#include "core/Log.h"
#include "gpu/CommonStates.h"
#include "gpu/Readback.h"
#include "render/FrameContext.h"
#include "tables/StagedComputation.h"

#include <algorithm>
#include <cstring>
#include <string>

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
      countsReadback_(device, DXGI_FORMAT_R32_UINT, 2) {}

void ParticleOpacity::resize(ID3D11Device* device, unsigned particleCapacity, int resolution) {
    const bool resized = resolution != resolution_;
    if (resized) {
        resolution_ = resolution;
        heads_ = createColorTexture(device, resolution, resolution + 1, DXGI_FORMAT_R32_UINT, D3D11_BIND_SHADER_RESOURCE | D3D11_BIND_UNORDERED_ACCESS);
        rasterTarget_ = createColorTexture(device, resolution, resolution, DXGI_FORMAT_R8_UNORM, D3D11_BIND_RENDER_TARGET);
    }
    if (particleCapacity != particleCapacity_ || resolution != poolResolution_) {
        poolResolution_ = resolution;
        particleCapacity_ = particleCapacity;
        transmittance_ = createStructuredBuffer(device, std::max(particleCapacity, 1u), 4, nullptr, "cloud particles' sun transmittance");
        // A particle covers about (its footprint / the tile)^2 tiles: 4x as many per doubling.
        const size_t perParticle = size_t{kNodesPerParticle} * static_cast<size_t>(resolution / 512 > 1 ? (resolution / 512) * (resolution / 512) : 1);
        capacity_ = static_cast<unsigned>(std::min<size_t>(size_t{particleCapacity} * perParticle, kMaxPoolBytes / kNodeStride));
        nodes_ = createStructuredBuffer(device, capacity_, kNodeStride, nullptr, "light-space tile nodes");
    }
}

void ParticleOpacity::compute(FrameContext& frame, CloudParticles& particles, const ParticleTables& tables, const CloudSettings& settings) {
    ID3D11DeviceContext* context = frame.context;
    computed_ = true;
    resize(frame.device, particles.capacity(), settings.lightSpaceResolution);
    if (const auto counts = countsReadback_.pollBits(context); counts && (*counts)[0] > capacity_ && capacity_ < kMaxPoolBytes / kNodeStride) {
        capacity_ = static_cast<unsigned>(std::min<size_t>(size_t{(*counts)[0]} * 5 / 4, kMaxPoolBytes / kNodeStride));
        nodes_ = createStructuredBuffer(frame.device, capacity_, kNodeStride, nullptr, "light-space tile nodes");
        log::info("clouds: the light-space tile pool grows to " + std::to_string(capacity_) + " nodes after a frame asked for " + std::to_string((*counts)[0]));
    }
    const glm::vec4 camera = frame.constants.cameraPosition, sun = frame.constants.directionToSun;
    constants_ = lightSpaceConstants(settings, glm::dvec3(camera.x, camera.y, camera.z), glm::dvec3(sun.x, sun.y, sun.z), capacity_);
    constantsBuffer_.update(context, constants_);
    const unsigned n = static_cast<unsigned>(resolution_);
    {
        auto pass = frame.profiler.scope("Clouds: light-space tiling");
        const UINT empty[4] = {0xffffffffu, 0xffffffffu, 0xffffffffu, 0xffffffffu};
        context->ClearUnorderedAccessViewUint(heads_.uav.Get(), empty);
        const UINT zero[2] = {};
        const D3D11_BOX counters{0, n, 0, 2, n + 1, 1};  // (1, n) is not used
        context->UpdateSubresource(heads_.texture.Get(), 0, &counters, zero, sizeof(zero), sizeof(zero));
        // Rasterized over the map with no colour written: the pixel shader appends to the lists.
        ID3D11RenderTargetView* target = rasterTarget_.rtv.Get();
        ID3D11UnorderedAccessView* views[] = {heads_.uav.Get(), nodes_.uav.Get()};
        context->OMSetRenderTargetsAndUnorderedAccessViews(1, &target, nullptr, 1, 2, views, nullptr);
        context->OMSetBlendState(noColourWrites_.Get(), nullptr, 0xffffffffu);
        context->OMSetDepthStencilState(nullptr, 0);
        context->RSSetState(noCulling_.Get());
        ID3D11Buffer* lightSpace = constantsBuffer_.get();
        context->VSSetConstantBuffers(2, 1, &lightSpace);
        context->PSSetConstantBuffers(2, 1, &lightSpace);
        particles.drawInstanced(frame, kTileVertexShader, kTilePixelShader, resolution_, resolution_);
        context->OMSetRenderTargets(0, nullptr, nullptr);
        context->OMSetBlendState(nullptr, nullptr, 0xffffffffu);
        // Each tile's list ordered from the sun.
        ID3D11Buffer* buffers[] = {frame.frameConstants, particles.fieldConstants(), lightSpace};
        context->CSSetConstantBuffers(0, 3, buffers);
        bindCompute(context, frame.shaders.computeShader(kOrderShader), {}, {heads_.uav.Get(), nodes_.uav.Get()});
        context->Dispatch(groupCount(n, 8), groupCount(n, 8), 1);
        unbindCompute(context, 0, 2);
        countsReadback_.copy(context, heads_.texture.Get(), 0, n);
    }
    {
        auto pass = frame.profiler.scope("Clouds: particle opacity");
        bindCompute(context, frame.shaders.computeShader(kOpacityShader),
                    {particles.sortedKeysView(), particles.particlesView(), tables.opticalDepth.srv.Get(), particles.argumentsView(), heads_.srv.Get(),
                     nodes_.srv.Get()},
                    {transmittance_.uav.Get()});
        context->CSSetSamplers(0, 1, linearWrap_.GetAddressOf());
        context->DispatchIndirect(particles.particleArguments(), 0);
        unbindCompute(context, 6, 1);
    }
}

void ParticleOpacity::clear(ID3D11Device* device, ID3D11DeviceContext* context, unsigned particleCapacity) {
    resize(device, particleCapacity, resolution_ > 0 ? resolution_ : 256);
    computed_ = false;
    const UINT one[4] = {0x3f800000u, 0x3f800000u, 0x3f800000u, 0x3f800000u};  // 1.0f
    context->ClearUnorderedAccessViewUint(transmittance_.uav.Get(), one);
}

ParticleOpacity::Counts ParticleOpacity::readCounts(ID3D11Device* device, ID3D11DeviceContext* context) const {
    Counts c;
    if (!heads_.texture) return c;
    const ReadbackImage heads = readTexture2D(device, context, heads_.texture.Get());
    unsigned counters[2] = {};
    std::memcpy(counters, heads.bytes.data() + static_cast<size_t>(resolution_) * static_cast<size_t>(resolution_) * 4u, sizeof(counters));
    c.nodes = counters[0];
    c.nodesDropped = counters[0] > capacity_ ? counters[0] - capacity_ : 0;
    return c;
}

}  // namespace firmament
