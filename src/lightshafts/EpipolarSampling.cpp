#include "lightshafts/EpipolarSampling.h"

#include "core/Camera.h"
#include "gpu/Hresult.h"
#include "tables/StagedComputation.h"

#include <glm/geometric.hpp>

#include <algorithm>
#include <cmath>
#include <string>

namespace firmament {

namespace {
// Thread groups of the passes (shaders/lightshafts/epipolar_inputs.hlsli).
constexpr unsigned kSampleGroup = 64;
constexpr unsigned kPixelGroup = 8;
// How far the epipole may lie from the screen's centre in NDC: beyond, the slices are parallel
// to the precision that matters, and the coordinates stay finite when the sun is at 90 degrees
// to the view.
constexpr float kMaxEpipoleDistance = 100.0f;
// The in-scattering criterion's floor, per unit sun irradiance: differences below a thousandth
// of the clear sky's typical in-scattering (about 0.1) never refine.
constexpr float kInscatteringFloor = 1.0e-4f;

ShaderKey computeKey(const char* file, std::vector<std::string> defines = {}) {
    return {std::string("lightshafts/") + file + ".hlsl", "main", "cs_5_0", std::move(defines)};
}
const ShaderKey kDotsVertexShader{"lightshafts/show_sampling.hlsl", "vs_main", "vs_5_0", {}};
const ShaderKey kDotsPixelShader{"lightshafts/show_sampling.hlsl", "ps_main", "ps_5_0", {}};
}  // namespace

EpipolarSampling::EpipolarSampling(ID3D11Device* device) : constants_(device), cascadePass_(device), noClouds_(device), states_(device) {}

glm::vec2 EpipolarSampling::epipole(const glm::mat4& viewProjection, glm::vec3 directionToSun, bool& behind) {
    const glm::vec4 clip = viewProjection * glm::vec4(directionToSun, 0.0f);
    behind = clip.w <= 0.0f;
    // Dividing by a negative w gives the anti-epipole: the projection of -directionToSun.
    const float w = std::abs(clip.w) > 1e-9f ? clip.w : (behind ? -1e-9f : 1e-9f);
    glm::vec2 e = glm::vec2(clip.x, clip.y) / w;
    const float distance = glm::length(e);
    if (distance > kMaxEpipoleDistance) e *= kMaxEpipoleDistance / distance;
    return e;
}

gpu::EpipolarConstants EpipolarSampling::constants(const LightShaftSettings& settings, const gpu::FrameConstants& frame, glm::vec3 cameraForward,
                                                   const ShadowInputs& shadows) {
    gpu::EpipolarConstants c{};
    c.sampling = glm::uvec4(static_cast<unsigned>(settings.slices), static_cast<unsigned>(settings.samplesPerSlice),
                            static_cast<unsigned>(settings.effectiveInitialStep()), static_cast<unsigned>(std::max(settings.epipoleDensity, 1)));
    c.options = glm::uvec4(settings.refinementCriterion == RefinementCriterion::Inscattering ? 1u : 0u, settings.optimizeSampleLocations ? 1u : 0u,
                           settings.correctDepthBreaks ? 1u : 0u, settings.showDepthBreaks ? 1u : 0u);
    c.modes = glm::uvec4(settings.extinction == ExtinctionEvaluation::Epipolar ? 1u : 0u, 0u, 0u, 0u);
    bool behind = false;
    const glm::vec2 e = epipole(frame.viewProjection, glm::vec3(frame.directionToSun), behind);
    // On the screen: within the rectangle of the outermost pixels' centres (epipolar_geometry.hlsli).
    const bool onScreen = std::abs(e.x) <= 1.0f - frame.screen.z && std::abs(e.y) <= 1.0f - frame.screen.w;
    c.epipole = glm::vec4(e, onScreen ? 1.0f : 0.0f, behind ? 1.0f : 0.0f);
    c.refinement = glm::vec4(settings.refinementThreshold, kInscatteringFloor, settings.depthRefinementThreshold(), 0.0f);
    c.cameraForward = glm::vec4(cameraForward, 0.0f);
    if (settings.minMaxOptimization && shadows.map && settings.firstCascade < shadows.cascades) {
        unsigned levels = 0;
        while ((1 << (levels + 1)) <= shadows.resolution) ++levels;
        c.trees = glm::uvec4(1u, static_cast<unsigned>(shadows.resolution), levels, settings.minMaxFormat == MinMaxFormat::Unorm16 ? 1u : 0u);
    }
    return c;
}

void EpipolarSampling::resize(ID3D11Device* device, int slices, int samples, int width, int height) {
    constexpr UINT kReadWrite = D3D11_BIND_SHADER_RESOURCE | D3D11_BIND_UNORDERED_ACCESS;
    if (width != width_ || height != height_) {
        cameraDepth_ = createColorTexture(device, width, height, DXGI_FORMAT_R32_FLOAT, kReadWrite);
        breakList_ = std::make_unique<WorkList>(device, static_cast<unsigned>(width * height));
        width_ = width;
        height_ = height;
    }
    if (slices != slices_ || samples != samplesPerSlice_) {
        sliceEnds_ = createColorTexture(device, slices, 1, DXGI_FORMAT_R32G32B32A32_FLOAT, kReadWrite);
        // A row per cascade there can be.
        sliceLines_ = createColorTexture(device, slices, kMaxCascades, DXGI_FORMAT_R32G32B32A32_FLOAT, kReadWrite);
        samples_ = createColorTexture(device, samples, slices, DXGI_FORMAT_R32G32B32A32_FLOAT, kReadWrite);
        coarse_ = createColorTexture(device, samples, slices, DXGI_FORMAT_R32G32B32A32_FLOAT, kReadWrite);
        extinction_ = createColorTexture(device, samples, slices, DXGI_FORMAT_R16G16B16A16_FLOAT, kReadWrite);
        sources_ = createColorTexture(device, samples, slices, DXGI_FORMAT_R16G16_UINT, kReadWrite);
        marched_ = createColorTexture(device, samples, slices, DXGI_FORMAT_R16G16B16A16_FLOAT, kReadWrite);
        interpolated_ = createColorTexture(device, samples, slices, DXGI_FORMAT_R16G16B16A16_FLOAT, kReadWrite);
        marchList_ = std::make_unique<WorkList>(device, static_cast<unsigned>(slices * samples));
        slices_ = slices;
        samplesPerSlice_ = samples;
    }
}

void EpipolarSampling::resizeTrees(ID3D11Device* device, int entries, int rows, MinMaxFormat format) {
    if (trees_.width == 2 * entries && trees_.height == rows && treeFormat_ == format) return;
    const DXGI_FORMAT dxgi = format == MinMaxFormat::Unorm16 ? DXGI_FORMAT_R16G16_UNORM : DXGI_FORMAT_R32G32_FLOAT;
    trees_ = createColorTexture(device, 2 * entries, rows, dxgi, D3D11_BIND_SHADER_RESOURCE | D3D11_BIND_UNORDERED_ACCESS);
    treeFormat_ = format;
}

bool EpipolarSampling::buildTrees(FrameContext& frame, const LightShaftSettings& settings, const ShadowInputs& shadows) {
    const int marched = shadows.cascades - settings.firstCascade;
    if (!settings.minMaxOptimization || !shadows.map || marched <= 0) return false;
    resizeTrees(frame.device, shadows.resolution, settings.slices * marched, settings.minMaxFormat);
    inputs_[SliceLines] = sliceLines_.srv.Get();
    {
        auto pass = frame.profiler.scope("Light shafts: slice lines in the shadow maps");
        run(frame, computeKey("slice_directions"), {sliceLines_.uav.Get()}, {SliceLines}, groupCount(static_cast<unsigned>(settings.slices), kSampleGroup),
            static_cast<unsigned>(shadows.cascades));
    }
    {
        auto pass = frame.profiler.scope("Light shafts: min/max trees");
        const bool unorm = settings.minMaxFormat == MinMaxFormat::Unorm16;
        run(frame, computeKey("build_minmax_trees", {unorm ? "MINMAX_UNORM=1" : "MINMAX_UNORM=0"}), {trees_.uav.Get()}, {Trees},
            static_cast<unsigned>(settings.slices * marched), 1);
    }
    inputs_[Trees] = trees_.srv.Get();
    return true;
}

void EpipolarSampling::run(FrameContext& frame, const ShaderKey& shader, std::initializer_list<ID3D11UnorderedAccessView*> outputs,
                           std::initializer_list<Input> written, unsigned groupsX, unsigned groupsY, const WorkList* list, bool layered) {
    ID3D11DeviceContext* context = frame.context;
    Inputs bound = inputs_;
    for (Input w : written) bound[w] = nullptr;
    context->CSSetShaderResources(0, InputCount, bound.data());
    context->CSSetUnorderedAccessViews(0, static_cast<UINT>(outputs.size()), outputs.begin(), nullptr);
    context->CSSetShader(frame.shaders.computeShader(shader), nullptr, 0);
    if (list) list->dispatch(context, layered);
    else context->Dispatch(groupsX, groupsY, 1);
    unbindCompute(context, InputCount, static_cast<unsigned>(outputs.size()));
}

void EpipolarSampling::prepareArguments(FrameContext& frame, const WorkList& list) {
    run(frame, computeKey("work_list_arguments"), {list.argumentsUav()}, {}, 1, 1);
}

void EpipolarSampling::render(FrameContext& frame, const LightShaftSettings& settings, const ScatteringLookup& lookup, const ShadowInputs& shadows,
                              ID3D11Buffer* lightShaftConstants, ID3D11Buffer* shadowConstants, const CloudShadowInputs& cloudInputs) {
    ID3D11DeviceContext* context = frame.context;
    const int slices = settings.slices, samples = settings.samplesPerSlice;
    const unsigned width = static_cast<unsigned>(frame.width()), height = static_cast<unsigned>(frame.height());
    resize(frame.device, slices, samples, frame.width(), frame.height());
    const gpu::EpipolarConstants c = constants(settings, frame.constants, frame.camera.forward(), shadows);
    CloudShadowInputs clouds = cloudInputs;
    if (!clouds.constants || !clouds.map) {
        noClouds_.update(context, gpu::CloudShadowConstants{});
        clouds = {noClouds_.get(), nullptr};
    }
    const bool trees = c.trees.x != 0;
    constants_.update(context, c);

    ID3D11ShaderResourceView* scene = frame.targets.copyHdr(context).srv.Get();
    inputs_ = {scene, frame.targets.depth().srv.Get(), lookup.netDensity, lookup.singleScattering, lookup.highOrderScattering,
               lookup.multipleScattering, shadows.map, cameraDepth_.srv.Get(), sliceEnds_.srv.Get(), samples_.srv.Get(), coarse_.srv.Get(),
               extinction_.srv.Get(), sources_.srv.Get(), marched_.srv.Get(), interpolated_.srv.Get(), nullptr, nullptr, nullptr, nullptr, nullptr,
               clouds.map};
    ID3D11Buffer* buffers[] = {frame.frameConstants, lookup.atmosphere, lightShaftConstants, shadowConstants, constants_.get(), cascadePass_.get(),
                               clouds.constants};
    std::copy(std::begin(buffers), std::end(buffers), constantBuffers_);
    ID3D11SamplerState* samplers[] = {lookup.linearClamp, shadows.comparison};
    context->CSSetConstantBuffers(0, 7, constantBuffers_);
    // The cascades the march goes through, and how.
    const int marchedCascades = shadows.map ? std::max(shadows.cascades - settings.firstCascade, 0) : 0;
    const CascadeProcessing cascadeMode = marchedCascades > 0 ? settings.effectiveCascadeProcessing(marchedCascades) : CascadeProcessing::SinglePass;
    cascadePass_.update(context, gpu::CascadePassConstants{glm::uvec4(0u, marchList_->capacity(), static_cast<unsigned>(std::max(marchedCascades, 1)), 0u)});
    context->CSSetSamplers(0, 2, samplers);
    // The unwarping writes the HDR target as a compute target: it must not stay bound for drawing.
    context->OMSetRenderTargets(0, nullptr, nullptr);

    const unsigned sampleGroups = groupCount(static_cast<unsigned>(samples), kSampleGroup);
    const unsigned rows = static_cast<unsigned>(slices);
    {
        auto pass = frame.profiler.scope("Light shafts: camera-space depth");
        run(frame, computeKey("camera_depth"), {cameraDepth_.uav.Get()}, {CameraDepth}, groupCount(width, kPixelGroup), groupCount(height, kPixelGroup));
    }
    {
        auto pass = frame.profiler.scope("Light shafts: slice end points");
        run(frame, computeKey("slice_endpoints"), {sliceEnds_.uav.Get()}, {SliceEnds}, groupCount(rows, kSampleGroup), 1);
    }
    {
        auto pass = frame.profiler.scope("Light shafts: sample coordinates");
        run(frame, computeKey("sample_coordinates"), {samples_.uav.Get()}, {Samples}, sampleGroups, rows);
    }
    {
        auto pass = frame.profiler.scope("Light shafts: coarse in-scattering");
        run(frame, computeKey("coarse_inscattering"), {coarse_.uav.Get(), extinction_.uav.Get()}, {Coarse, Extinction}, sampleGroups, rows);
    }
    {
        auto pass = frame.profiler.scope("Light shafts: refinement");
        run(frame, computeKey("refine_samples"), {sources_.uav.Get()}, {Sources}, rows, 1);
    }
    {
        auto pass = frame.profiler.scope("Light shafts: marking");
        marchList_->clear(context);
        run(frame, computeKey("mark_samples"), {marchList_->itemsUav(), marchList_->argumentsUav()}, {}, sampleGroups, rows);
        prepareArguments(frame, *marchList_);
    }
    if (trees) buildTrees(frame, settings, shadows);
    {
        auto pass = frame.profiler.scope("Light shafts: ray marching");
        inputs_[List] = marchList_->itemsSrv();
        inputs_[ListArguments] = marchList_->argumentsSrv();
        march(frame, cascadeMode, marchedCascades);
    }
    {
        auto pass = frame.profiler.scope("Light shafts: interpolation");
        run(frame, computeKey("interpolate_samples"), {interpolated_.uav.Get()}, {Interpolated}, sampleGroups, rows);
    }
    ID3D11UnorderedAccessView* hdr = frame.targets.hdr().uav.Get();
    {
        auto pass = frame.profiler.scope("Light shafts: unwarping");
        inputs_[List] = inputs_[ListArguments] = nullptr;
        breakList_->clear(context);
        run(frame, computeKey("unwarp"), {hdr, breakList_->itemsUav(), breakList_->argumentsUav()}, {}, groupCount(width, kPixelGroup),
            groupCount(height, kPixelGroup));
        prepareArguments(frame, *breakList_);
    }
    {
        auto pass = frame.profiler.scope("Light shafts: correction at depth breaks");
        inputs_[List] = breakList_->itemsSrv();
        inputs_[ListArguments] = breakList_->argumentsSrv();
        run(frame, computeKey("correct_depth_breaks"), {hdr}, {}, 0, 0, breakList_.get());
        inputs_[List] = inputs_[ListArguments] = nullptr;
    }
    if (settings.showSampling) {
        auto pass = frame.profiler.scope("Light shafts: show sampling");
        showSampling(frame, slices, samples);
    }
}

void EpipolarSampling::march(FrameContext& frame, CascadeProcessing mode, int marchedCascades) {
    if (mode == CascadeProcessing::SinglePass) {
        run(frame, computeKey("march_samples"), {marched_.uav.Get()}, {Marched}, 0, 0, marchList_.get());
        return;
    }
    // Room for every listed sample's part of every cascade.
    const unsigned capacity = marchList_->capacity();
    const unsigned parts = capacity * static_cast<unsigned>(marchedCascades);
    if (parts > cascadePartCount_) {
        cascadeParts_ = createStructuredBuffer(frame.device, parts, 32, nullptr, "cascade parts");
        cascadePartCount_ = parts;
    }
    const ShaderKey marchCascades = computeKey("march_cascades");
    if (mode == CascadeProcessing::MultiPass) {
        for (int k = 0; k < marchedCascades; ++k) {
            cascadePass_.update(frame.context, gpu::CascadePassConstants{glm::uvec4(static_cast<unsigned>(k), capacity, 1u, 0u)});
            run(frame, marchCascades, {cascadeParts_.uav.Get()}, {CascadeParts}, 0, 0, marchList_.get());
        }
    } else {
        cascadePass_.update(frame.context, gpu::CascadePassConstants{glm::uvec4(0u, capacity, static_cast<unsigned>(marchedCascades), 0u)});
        run(frame, marchCascades, {cascadeParts_.uav.Get()}, {CascadeParts}, 0, 0, marchList_.get(), true);
    }
    inputs_[CascadeParts] = cascadeParts_.srv.Get();
    run(frame, computeKey("combine_cascades"), {marched_.uav.Get()}, {Marched}, 0, 0, marchList_.get());
    inputs_[CascadeParts] = nullptr;
}

void EpipolarSampling::showSampling(FrameContext& frame, int slices, int samples) {
    ID3D11DeviceContext* context = frame.context;
    states_.bindTarget(context, frame.targets.hdr().rtv.Get(), frame.width(), frame.height());
    context->VSSetConstantBuffers(0, 7, constantBuffers_);
    context->VSSetShaderResources(0, InputCount, inputs_.data());
    context->VSSetShader(frame.shaders.vertexShader(kDotsVertexShader), nullptr, 0);
    context->PSSetShader(frame.shaders.pixelShader(kDotsPixelShader), nullptr, 0);
    context->Draw(static_cast<UINT>(6 * slices * samples), 0);
    ID3D11ShaderResourceView* none[InputCount] = {};
    context->VSSetShaderResources(0, InputCount, none);
}

}  // namespace firmament
