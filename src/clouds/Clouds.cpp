#include "clouds/Clouds.h"

#include "core/Log.h"
#include "frame/FrameContext.h"
#include "gpu/CommonStates.h"
#include "gpu/Readback.h"
#include "tables/TimeTables.h"

#include <algorithm>
#include <array>
#include <cstring>
#include <optional>
#include <string>

namespace firmament {

namespace {
const ShaderKey kOpticalDepthVertexShader{"clouds/optical_depth_view.hlsl", "vs_main", "vs_5_0", {}};
const ShaderKey kOpticalDepthPixelShader{"clouds/optical_depth_view.hlsl", "ps_main", "ps_5_0", {}};
// The shading's shaders through the tables of the model `atmosphere` (CLOUD_ATMOSPHERE: 1 Yusov
// 2013, 2 Bruneton 2008, 3 Hillaire 2020); the pixel shader's for each blending path
// (CLOUD_BLENDING=0 alpha, 1 per-pixel lists, 2 ordered views).
ShaderKey shadeVertexKey(int atmosphere) { return {"clouds/shade_particles.hlsl", "vs_main", "vs_5_0", {cloudAtmosphereDefine(atmosphere)}}; }
ShaderKey shadePixelKey(int atmosphere, ParticleBlending blending) {
    const char* path = blending == ParticleBlending::PerPixelLists ? "CLOUD_BLENDING=1" : blending == ParticleBlending::RasterizerOrdered ? "CLOUD_BLENDING=2" : "CLOUD_BLENDING=0";
    return {"clouds/shade_particles.hlsl", "ps_main", "ps_5_0", {cloudAtmosphereDefine(atmosphere), path}};
}

// The tables the clouds are lit through, where clouds/cloud_atmosphere.hlsli reads them.
struct AtmosphereBinding {
    int model = 0;                                           // CLOUD_ATMOSPHERE; 0: no model's tables are ready
    ID3D11Buffer* atmosphere = nullptr;                      // b2: AtmosphereConstants
    ID3D11Buffer* modelConstants = nullptr;                  // b4: Bruneton's or Hillaire's constants
    std::array<ID3D11ShaderResourceView*, 5> tables{};       // t5..t9
    ID3D11SamplerState* linearClamp = nullptr;
    glm::uvec4 modes{0u};                                    // Yusov's render modes: single, multiple, integration steps
};

AtmosphereBinding bindingOf(const Clouds::AtmosphereTables& a) {
    AtmosphereBinding b;
    if (const ScatteringLookup* y = a.yusov; y && y->ready) {
        b = {1, y->atmosphere, nullptr, {y->netDensity, y->singleScattering, y->highOrderScattering, y->multipleScattering, y->ambientLight},
             y->linearClamp,
             glm::uvec4(static_cast<unsigned>(y->singleMode), static_cast<unsigned>(y->multipleMode), static_cast<unsigned>(y->integrationSteps), 0u)};
    } else if (const BrunetonLookup* br = a.bruneton; br && br->ready) {
        b = {2, br->atmosphere, br->bruneton, {br->transmittance, br->irradiance, br->inscatter, nullptr, nullptr}, br->linearClamp, glm::uvec4(0u)};
    } else if (const HillaireLookup* h = a.hillaire; h && h->ready) {
        b = {3, h->atmosphere, h->hillaire, {h->transmittance, h->multipleScattering, h->irradiance, nullptr, nullptr}, h->linearClamp, glm::uvec4(0u)};
    }
    return b;
}
}  // namespace

Clouds::Clouds(ID3D11Device* device, const TableStorage& storage)
    : storage_(storage),
      tables_("clouds", "Clouds: particle tables"),
      particles_(device),
      linearWrap_(states::linearWrap(device)),
      premultiplied_(states::premultipliedAlpha(device)),
      noCulling_(states::cullNone(device)),
      shadingConstants_(device),
      blendingSupport_(queryBlendingSupport(device)),
      blending_(device),
      lowResolution_(device),
      opacity_(device),
      shadowMap_(device),
      reference_(device) {
    log::info(std::string("clouds: the device ") + (blendingSupport_.rasterizerOrderedViews ? "supports" : "has no") +
              " rasterizer-ordered views; Blending path Auto: " +
              std::string(describeParticleBlending(chooseParticleBlending(true, BlendingPath::Auto, blendingSupport_))));
}

ParticleTableParameters Clouds::tableParameters(const CloudSettings& settings) {
    ParticleTableParameters p;
    p.method = settings.particleDensity;
    return p;
}

void Clouds::updateTables(FrameContext& frame, const CloudSettings& settings, bool finishNow) {
    const ParticleTableParameters wanted = tableParameters(settings);
    tables_.update(frame.device, frame.context, frame.shaders, frame.profiler, storage_, particleTableKey(wanted, frame.shaders),
                   [&] { return std::make_unique<ParticleTablePrecomputation>(frame.device, wanted); }, finishNow);
}

TableTiming Clouds::timeTables(ID3D11Device* device, ID3D11DeviceContext* context, ShaderLibrary& shaders, const CloudSettings& settings,
                               const std::filesystem::path& scratch) {
    const ParticleTableParameters p = tableParameters(settings);
    return firmament::timeTables(
        "Cloud particle (optical depth)", particleTableKey(p, shaders), [&] { return std::make_unique<ParticleTablePrecomputation>(device, p); }, device,
        context, shaders, scratch);
}

std::vector<std::pair<std::string, double>> Clouds::counts(ID3D11Device* device, ID3D11DeviceContext* context) {
    const auto read = [&](ID3D11Buffer* arguments) {
        const std::vector<std::uint8_t> bytes = readBuffer(device, context, arguments);
        unsigned values[8] = {};
        std::memcpy(values, bytes.data(), std::min(bytes.size(), sizeof(values)));
        return static_cast<double>(values[3]);
    };
    const double cells = read(particles_.validCells().arguments()), generated = read(particles_.particleArguments());
    const double capacity = static_cast<double>(particles_.capacity());
    const double kept = std::min(generated, capacity);
    const double drawn = particles_.visibleArguments() ? read(particles_.visibleArguments()) : kept;
    std::vector<std::pair<std::string, double>> result{{"cloud valid cells", cells},
                                                       {"cloud particles", kept},
                                                       {"cloud particles over capacity", std::max(generated - capacity, 0.0)},
                                                       {"cloud particles drawn", drawn}};
    // Which volume-aware path ran (1: rasterizer-ordered views, 0: the lists or alpha), and what
    // its resources hold.
    result.emplace_back("cloud blending through rasterizer-ordered views", blending_.path() == ParticleBlending::RasterizerOrdered ? 1.0 : 0.0);
    result.emplace_back("cloud blending memory (MiB)", static_cast<double>(blending_.memoryBytes()) / (1024.0 * 1024.0));
    if (blending_.path() == ParticleBlending::PerPixelLists) {
        const VolumeBlendingPass::Overflow o = blending_.readOverflow(device, context);
        result.emplace_back("cloud fragments", static_cast<double>(o.nodesAskedFor));
        result.emplace_back("cloud fragments over the node pool", static_cast<double>(o.nodesDropped));
        result.emplace_back("cloud fragments over a pixel's limit", static_cast<double>(o.fragmentsDropped));
    }
    if (referenceDrawn_) result.emplace_back("cloud reference paths", static_cast<double>(reference_.pathsLastPass()));
    if (opacity_.computed()) {
        const ParticleOpacity::Counts o = opacity_.readCounts(device, context);
        result.emplace_back("cloud light-space tile nodes", static_cast<double>(o.nodes));
        result.emplace_back("cloud light-space tile nodes over the pool", static_cast<double>(o.nodesDropped));
    }
    return result;
}

std::string Clouds::blendingStatus() const {
    if (referenceDrawn_) {
        std::string status = "Reference (path traced): " + std::to_string(reference_.pathsPerPixel()) + " paths per pixel";
        const unsigned blockPixels = reference_.stride() * reference_.stride();
        if (blockPixels > 1)
            status += ", pass " + std::to_string((reference_.passes() - 1) % blockPixels + 1) + " of " + std::to_string(blockPixels) + " of the next round";
        return status;
    }
    std::string status(describeParticleBlending(blending_.path()));
    if (blending_.path() == ParticleBlending::PerPixelLists) {
        if (const std::optional<VolumeBlendingPass::Overflow> o = blending_.latestOverflow())
            status += ": " + std::to_string(o->nodesAskedFor) + " fragments in a pool of " + std::to_string(blending_.nodeCapacity()) + ", " +
                      std::to_string(o->nodesDropped) + " dropped, " + std::to_string(o->fragmentsDropped) + " past a pixel's limit of " + std::to_string(gpu::kMaxPixelFragments);
    }
    return status;
}

std::optional<double> Clouds::tableProgress() const {
    if (const ParticleTablePrecomputation* pending = tables_.pending()) return pending->progress();
    return std::nullopt;
}

void Clouds::update(FrameContext& frame, const CloudSettings& settings) {
    if (settings.showParticles == ParticleView::Off && !settings.enabled) {
        shadowMap_.clear(frame.context);
        return;
    }
    const OpticalDepthTableSize& n = tableParameters(settings).opticalDepth;
    const bool reference = settings.enabled && settings.renderer == CloudRenderer::PathTracedReference && settings.showParticles == ParticleView::Off;
    if (!reference) referenceSeconds_.reset();
    else if (!referenceSeconds_) referenceSeconds_ = frame.timeSeconds;
    FrameContext clock = frame;  // the particles' time: frozen while the reference accumulates
    if (referenceSeconds_) clock.timeSeconds = *referenceSeconds_;
    particles_.update(clock, settings,
                      glm::vec4(static_cast<float>(n.entryZenith), static_cast<float>(n.entryAzimuth), static_cast<float>(n.directionZenith),
                                static_cast<float>(n.directionAzimuth)));
    if (settings.showParticles != ParticleView::BoundingShapes) updateTables(frame, settings, frame.finishWorkNow);
    const ParticleTablePrecomputation* tables = tables_.current();
    if (reference) reference_.buildIndex(frame, particles_, settings);
    if (settings.enabled && settings.showParticles == ParticleView::Off && tables) {
        scatteringTable(frame.device);
        if (settings.multipleScattering == MultipleScattering::SolvedSlab) deckDiffusionTable(frame.device);
        if (settings.lightOcclusion && !reference) opacity_.compute(frame, particles_, tables->tables(), settings);
        else opacity_.clear(frame.device, frame.context, particles_.capacity());
        if (settings.shadows) shadowMap_.render(frame, particles_, tables->tables(), settings);
        else shadowMap_.clear(frame.context);
    } else {
        if (settings.enabled && settings.showParticles == ParticleView::Off) opacity_.clear(frame.device, frame.context, particles_.capacity());
        shadowMap_.clear(frame.context);
    }
}

void Clouds::renderGeometry(FrameContext& frame, const CloudSettings& settings) {
    if (settings.showParticles == ParticleView::BoundingShapes) particles_.drawBoundingShapes(frame);
}

// Show particles replaces the shaded clouds with its view of them.
void Clouds::renderTranslucent(FrameContext& frame, const CloudSettings& settings, AtmosphereTables atmosphere) {
    const ParticleTablePrecomputation* tables = tables_.current();
    if (!tables) return;
    const bool lit = bindingOf(atmosphere).model != 0;
    referenceDrawn_ = false;
    if (settings.showParticles == ParticleView::OpticalDepth) drawOpticalDepth(frame, tables->tables());
    else if (settings.showParticles == ParticleView::Off && settings.enabled && lit && settings.renderer == CloudRenderer::PathTracedReference)
        drawReference(frame, settings, atmosphere);
    else if (settings.showParticles == ParticleView::Off && settings.enabled && lit)
        drawShaded(frame, tables->tables(), atmosphere, chooseParticleBlending(settings.volumetricBlending, settings.blendingPath, blendingSupport_),
                   settings);
}

const Texture3D& Clouds::scatteringTable(ID3D11Device* device) {
    if (scattering_.texture) return scattering_;
    const std::filesystem::path path = storage_.mediaFolder / "clouds" / "particle-scattering.exr";
    const ParticleScatteringTable table = readParticleScattering(path, scatteringParameters_);
    const ParticleScatteringParameters& p = table.parameters;
    std::vector<float> texels(table.single.size() * 4, 0.0f);
    for (size_t k = 0; k < table.single.size(); ++k) {
        texels[4 * k] = table.single[k];
        texels[4 * k + 1] = table.multiple[k];
        texels[4 * k + 2] = table.peak[k];
    }
    // One block of viewZeniths slices per optical radius.
    scattering_ = createTexture3D(device, p.entryAngles, p.viewAzimuths, p.viewZeniths * p.opticalRadii, DXGI_FORMAT_R32G32B32A32_FLOAT,
                                  D3D11_BIND_SHADER_RESOURCE);
    ComPtr<ID3D11DeviceContext> context;
    device->GetImmediateContext(&context);
    context->UpdateSubresource(scattering_.texture.Get(), 0, nullptr, texels.data(), static_cast<UINT>(p.entryAngles * 16),
                               static_cast<UINT>(p.entryAngles * p.viewAzimuths * 16));
    log::info("clouds: particle scattering table read from " + path.string());
    return scattering_;
}

const Texture3D& Clouds::deckDiffusionTable(ID3D11Device* device) {
    if (deckDiffusion_.texture) return deckDiffusion_;
    const std::filesystem::path path = storage_.mediaFolder / "clouds" / "deck-diffusion.exr";
    const DeckDiffusionTable table = readDeckDiffusion(path, deckParameters_);
    const DeckDiffusionParameters& p = table.parameters;
    deckDiffusion_ = createTexture3D(device, p.cosines, p.depths, p.thicknesses, DXGI_FORMAT_R32_FLOAT, D3D11_BIND_SHADER_RESOURCE);
    ComPtr<ID3D11DeviceContext> context;
    device->GetImmediateContext(&context);
    context->UpdateSubresource(deckDiffusion_.texture.Get(), 0, nullptr, table.multiple.data(), static_cast<UINT>(p.cosines * 4),
                               static_cast<UINT>(p.cosines * p.depths * 4));
    log::info("clouds: deck diffusion's table read from " + path.string());
    return deckDiffusion_;
}

// Back to front, premultiplied alpha, no depth target: the pixel shader cuts each particle at the
// scene's depth. At 1x straight over the frame; at 2x and 4x into the low-resolution target, cut
// by its depth, then upsampled over the frame.
void Clouds::drawShaded(FrameContext& frame, const ParticleTables& tables, AtmosphereTables atmosphere, ParticleBlending blending,
                        const CloudSettings& settings) {
    const int downscale = settings.downscale;
    ID3D11DeviceContext* context = frame.context;
    const Texture3D& scattering = scatteringTable(frame.device);
    // Deck diffusion's table only where the comparison mode samples it; else nothing is bound.
    ID3D11ShaderResourceView* deck =
        settings.multipleScattering == MultipleScattering::SolvedSlab ? deckDiffusionTable(frame.device).srv.Get() : nullptr;
    const AtmosphereBinding air = bindingOf(atmosphere);
    gpu::CloudShadingConstants c{};
    c.modes = air.modes;
    c.scattering = glm::vec4(static_cast<float>(scatteringParameters_.entryAngles), static_cast<float>(scatteringParameters_.viewAzimuths),
                             static_cast<float>(scatteringParameters_.viewZeniths), static_cast<float>(scatteringParameters_.opticalRadii));
    c.light = glm::vec4(static_cast<float>(scatteringParameters_.firstOpticalRadius), static_cast<float>(settings.multipleScattering),
                        static_cast<float>(deckParameters_.thinnest), static_cast<float>(settings.lightTerms));
    c.deck = glm::vec4(static_cast<float>(deckParameters_.cosines), static_cast<float>(deckParameters_.depths), static_cast<float>(deckParameters_.thicknesses),
                       static_cast<float>(deckParameters_.thicknessesPerOctave));
    ID3D11RenderTargetView* hdr = frame.targets.hdr().rtv.Get();
    ID3D11RenderTargetView* target = hdr;
    ID3D11ShaderResourceView* depth = frame.targets.depth().srv.Get();
    ID3D11BlendState* blend = nullptr;  // the blending pass's premultiplied alpha
    int width = frame.width(), height = frame.height();
    if (downscale > 1) {
        auto low = frame.profiler.scope("Clouds: low-resolution depth");
        lowResolution_.begin(frame.device, context, frame.shaders, depth, width, height, downscale);
        target = lowResolution_.clouds().rtv.Get();
        depth = lowResolution_.depth().srv.Get();
        blend = lowResolution_.blendState();
        width = lowResolution_.clouds().width;
        height = lowResolution_.clouds().height;
    }
    // The passes are timed one after another, none inside another.
    std::optional<GpuProfiler::Scope> pass;
    pass.emplace(frame.profiler, "Clouds: shading");
    // The first per-pixel lists of a new pool (at start, at a new size) that did not fit it are
    // drawn again into a larger one, so that no frame after a resize loses fragments.
    do {
        blending_.begin(frame.device, context, blending, width, height);
        c.blending = glm::uvec4(blending_.nodeCapacity(), static_cast<unsigned>(height), 0u, 0u);
        c.target = glm::vec4(static_cast<float>(width), static_cast<float>(height), 1.0f / static_cast<float>(width), 1.0f / static_cast<float>(height));
        shadingConstants_.update(context, c);
        blending_.bindForParticles(context, target, blend);
        context->OMSetDepthStencilState(nullptr, 0);
        context->RSSetState(noCulling_.Get());
        ID3D11Buffer* buffers[] = {air.atmosphere, shadingConstants_.get(), air.modelConstants};
        context->PSSetConstantBuffers(2, 3, buffers);
        ID3D11ShaderResourceView* extra[3] = {tables.opticalDepth.srv.Get(), depth, scattering.srv.Get()};
        context->PSSetShaderResources(2, 3, extra);
        context->PSSetShaderResources(5, 5, air.tables.data());
        ID3D11ShaderResourceView* sunColumn = opacity_.sunColumn();
        context->PSSetShaderResources(10, 1, &sunColumn);
        context->PSSetShaderResources(11, 1, &deck);
        ID3D11SamplerState* samplers[] = {linearWrap_.Get(), air.linearClamp};
        context->PSSetSamplers(0, 2, samplers);
        particles_.drawInstanced(frame, shadeVertexKey(air.model), shadePixelKey(air.model, blending), ParticleSet::InView, width, height);
        ID3D11ShaderResourceView* none[10] = {};
        context->PSSetShaderResources(2, 10, none);
    } while (blending_.firstBuildOverflowed(frame.device, context));
    pass.reset();
    if (blending != ParticleBlending::Alpha) {
        auto resolvePass = frame.profiler.scope("Clouds: blending resolve");
        blending_.resolve(context, frame.shaders, target, blend);
    }
    if (downscale > 1) {
        auto upsample = frame.profiler.scope("Clouds: upsample");
        lowResolution_.upsample(context, frame.shaders, frame.targets.depth().srv.Get(), hdr, frame.width(), frame.height());
    }
    context->OMSetRenderTargets(1, &hdr, nullptr);
    context->OMSetBlendState(nullptr, nullptr, 0xffffffffu);
}

namespace {
// FNV-1a over bytes: the reference's digest of what its picture depends on.
std::uint64_t digest(std::uint64_t hash, const void* data, size_t size) {
    const auto* bytes = static_cast<const unsigned char*>(data);
    for (size_t k = 0; k < size; ++k) hash = (hash ^ bytes[k]) * 0x100000001b3ull;
    return hash;
}
}  // namespace

void Clouds::drawReference(FrameContext& frame, const CloudSettings& settings, AtmosphereTables atmosphere) {
    ID3D11DeviceContext* context = frame.context;
    const AtmosphereBinding air = bindingOf(atmosphere);
    const glm::uvec4 modes = air.modes;
    // Everything the picture depends on but the clock, which the reference holds still.
    gpu::FrameConstants view = frame.constants;
    view.time = glm::vec4(0.0f);
    std::uint64_t key = digest(0xcbf29ce484222325ull, &view, sizeof view);
    key = digest(key, &particles_.constants(), sizeof(gpu::CloudFieldConstants));
    const unsigned choices[] = {static_cast<unsigned>(settings.particleDensity), static_cast<unsigned>(air.model), modes.x, modes.y, modes.z};
    key = digest(key, choices, sizeof choices);
    ID3D11Buffer* buffers[] = {air.atmosphere};
    context->CSSetConstantBuffers(2, 1, buffers);
    ID3D11Buffer* modelBuffer = air.modelConstants;
    context->CSSetConstantBuffers(4, 1, &modelBuffer);
    context->CSSetShaderResources(5, 5, air.tables.data());
    ID3D11SamplerState* clamp = air.linearClamp;
    context->CSSetSamplers(1, 1, &clamp);
    reference_.trace(frame, particles_, settings, key, air.model, modes);
    referenceDrawn_ = true;
}

// Back to front, premultiplied alpha, no depth target: the pixel shader cuts each particle at the
// scene's depth, which it reads.
void Clouds::drawOpticalDepth(FrameContext& frame, const ParticleTables& tables) {
    ID3D11DeviceContext* context = frame.context;
    auto pass = frame.profiler.scope("Clouds: particles' optical depth");
    ID3D11RenderTargetView* hdr = frame.targets.hdr().rtv.Get();
    context->OMSetRenderTargets(1, &hdr, nullptr);
    context->OMSetBlendState(premultiplied_.Get(), nullptr, 0xffffffffu);
    context->OMSetDepthStencilState(nullptr, 0);
    context->RSSetState(noCulling_.Get());
    ID3D11ShaderResourceView* extra[] = {tables.opticalDepth.srv.Get(), frame.targets.depth().srv.Get()};
    context->PSSetShaderResources(2, 2, extra);
    context->PSSetSamplers(0, 1, linearWrap_.GetAddressOf());
    particles_.drawInstanced(frame, kOpticalDepthVertexShader, kOpticalDepthPixelShader, ParticleSet::InView);
    ID3D11ShaderResourceView* none[2] = {};
    context->PSSetShaderResources(2, 2, none);
    context->OMSetBlendState(nullptr, nullptr, 0xffffffffu);
}

}  // namespace firmament
