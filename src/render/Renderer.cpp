#include "render/Renderer.h"

#include "atmosphere/Atmosphere.h"
#include "atmosphere/AtmosphereParameters.h"
#include "clouds/Clouds.h"
#include "frame/FrameContext.h"
#include "lightshafts/LightShafts.h"
#include "postfx/ToneMapping.h"
#include "scene/OrientationGridPass.h"
#include "settings/State.h"
#include "shadows/CascadedShadowMaps.h"
#include "terrain/ClipmapLayout.h"
#include "terrain/HeightFieldFile.h"
#include "terrain/Terrain.h"

#include <algorithm>

namespace firmament {

namespace {
// Linear radiance of the HDR frame where no pass draws (everything off but the tone mapping).
constexpr float kBackground[4] = {0.02f, 0.025f, 0.035f, 1.0f};
}  // namespace

Renderer::Renderer(ID3D11Device* device, ID3D11DeviceContext* context, ShaderLibrary& shaders, const TableStorage& tables)
    : device_(device),
      context_(context),
      shaders_(shaders),
      tables_(tables),
      profiler_(device, context),
      frameConstants_(device),
      orientationGrid_(std::make_unique<OrientationGridPass>(device)),
      atmosphere_(std::make_unique<Atmosphere>(device, tables)),
      shadows_(std::make_unique<CascadedShadowMaps>(device)),
      lightShafts_(std::make_unique<LightShafts>(device)),
      clouds_(std::make_unique<Clouds>(device, tables)),
      toneMapping_(std::make_unique<ToneMapping>(device)) {}

Renderer::~Renderer() = default;

void Renderer::startOver() {
    // The techniques' GPU objects go before their replacements are made (the clouds' pools are large).
    orientationGrid_.reset();
    shadows_.reset();
    lightShafts_.reset();
    clouds_.reset();
    toneMapping_.reset();
    orientationGrid_ = std::make_unique<OrientationGridPass>(device_);
    shadows_ = std::make_unique<CascadedShadowMaps>(device_);
    lightShafts_ = std::make_unique<LightShafts>(device_);
    clouds_ = std::make_unique<Clouds>(device_, tables_);
    toneMapping_ = std::make_unique<ToneMapping>(device_);
}

void Renderer::resize(int width, int height, bool ownOutput, HdrPrecision precision) {
    targets_.resize(device_, width, height, ownOutput, precision);
}

// The frame order (docs/architecture.md, "The frame", numbers its steps as these comments do).
// Each step is one technique's pass or passes. What one technique hands another (the ground's
// lighting, the shadow cascades, the clouds' shadows, the atmosphere's look-ups) is handed here
// and nowhere else: no technique includes another's header.
void Renderer::render(const State& state, FrameTime time, bool finishWorkNow, ID3D11RenderTargetView* output,
                      const std::function<void(ID3D11RenderTargetView*)>& drawGui) {
    if (!output) output = targets_.output().rtv.Get();
    profiler_.beginFrame();
    const Camera camera = viewCamera(state);
    const gpu::FrameConstants constants = frameConstants(state, camera, time);
    frameConstants_.update(context_, constants);
    FrameContext frame{device_, context_, shaders_, profiler_, targets_, frameConstants_.get(), constants, camera, state.sun,
                       time.seconds, time.deltaSeconds, finishWorkNow};
    // 1. The frame's targets cleared.
    {
        auto pass = profiler_.scope("Clear frame targets");
        context_->ClearRenderTargetView(targets_.hdr().rtv.Get(), kBackground);
        context_->ClearDepthStencilView(targets_.depth().dsv.Get(), D3D11_CLEAR_DEPTH, 0.0f, 0);  // reversed Z: 0 is the far plane
    }
    // 2. The atmosphere's tables, when its settings changed (a window spreads the work over
    //    frames and shows the grid's own sky until they are ready).
    atmosphere_->update(frame, state.atmosphere);
    const bool scattering = atmosphere_->ready(state.atmosphere);
    // 3. The orientation grid: its ground alone under the atmosphere, else its own sky too.
    if (state.scene.orientationGrid) {
        auto pass = profiler_.scope("Orientation grid");
        orientationGrid_->render(frame, scattering);
    }
    // 4. The clouds' particles, generated and sorted on the GPU, their tables, their light
    //    occlusion and their shadow map: before the terrain, which they shadow.
    clouds_->update(frame, state.clouds);
    // 5. The shadow cascades, then 6. the terrain lit by the atmosphere's tables through them and
    //    the clouds' shadows.
    if (state.terrain.enabled) renderShadowsAndTerrain(frame, state);
    // 7. The particles' view as geometry (Show particles: bounding shapes).
    clouds_->renderGeometry(frame, state.clouds);
    // 8. The sky and the sun where nothing was drawn, 9. the aerial perspective over geometry:
    //    with light shafts, both in their pass, through the shadow cascades drawn this frame and,
    //    by "Shafts from clouds", the clouds (drawn into the cascades, or their transparency map).
    if (lightShaftsDrawn(state)) {
        const ShaftsFromClouds fromClouds = clouds_->shadowMap().active() ? state.clouds.shaftsFromClouds : ShaftsFromClouds::None;
        if (fromClouds == ShaftsFromClouds::ShadowMap && state.terrain.enabled) drawCloudsIntoCascades(frame);
        const ShadowInputs shadows = state.terrain.enabled ? shadows_->inputs() : ShadowInputs{};
        const CloudShadowInputs cloudShadows = fromClouds == ShaftsFromClouds::TransparencyMap ? clouds_->shadows() : CloudShadowInputs{};
        lightShafts_->render(frame, state.lightShafts, atmosphere_->scatteringLookup(frame, state.atmosphere), shadows, cloudShadows);
    } else {
        atmosphere_->renderSky(frame, state.atmosphere);
        atmosphere_->renderAerialPerspective(frame, state.atmosphere);
    }
    // 10. The clouds, shaded through the tables of the atmosphere model drawn alone (or the
    //     particles' translucent view), over the lit scene.
    {
        const AtmosphereSettings& a = state.atmosphere;
        const bool alone = a.comparison == ModelComparison::None && scattering && state.clouds.enabled;
        const bool yusov = alone && a.model == AtmosphereModel::Yusov2013, bruneton = alone && a.model == AtmosphereModel::Bruneton2008,
                   hillaire = alone && a.model == AtmosphereModel::Hillaire2020;
        const ScatteringLookup yusovTables = yusov ? atmosphere_->scatteringLookup(frame, a) : ScatteringLookup{};
        const BrunetonLookup brunetonTables = bruneton ? atmosphere_->brunetonLookup(frame, a) : BrunetonLookup{};
        const HillaireLookup hillaireTables = hillaire ? atmosphere_->hillaireLookup(frame, a) : HillaireLookup{};
        clouds_->renderTranslucent(frame, state.clouds,
                                   {yusov ? &yusovTables : nullptr, bruneton ? &brunetonTables : nullptr, hillaire ? &hillaireTables : nullptr});
    }
    // 11. Luminance, exposure, adaptation and tone mapping to the output.
    toneMapping_->render(frame, state.toneMapping, output);
    // 12. The GUI over the output.
    if (drawGui) {
        auto pass = profiler_.scope("GUI");
        drawGui(output);
    }
    profiler_.endFrame();
}

// The cascades fit the camera; the terrain is their only caster (the clouds join it for the
// light shafts with "Shafts from clouds: shadow map", after the terrain is drawn). Casters may stand as far
// towards the sun as the highest peak can be seen above the sun's elevation, within 200 km.
void Renderer::renderShadowsAndTerrain(FrameContext& frame, const State& state) {
    Terrain& terrain = this->terrain();
    terrain.place(glm::dvec3(state.camera.position));
    const glm::dvec3 toSun = glm::dvec3(state.sun.direction());
    const double reach = std::min((terrain.maxAltitude() - terrain.minAltitude() + 1000.0) / std::max(toSun.y, 0.02), 2.0e5);
    // The light shafts' march starts at the camera: their first marched cascade holds it.
    const int aroundCamera = lightShaftsDrawn(state) ? state.lightShafts.firstCascade : -1;
    // The cascades split the view from state.camera's own near plane (1 m), not the fitted one: from
    // high up their reach ends before the fitted plane, and nothing there casts into the view.
    shadows_->update(frame.context, state.camera, static_cast<double>(frame.width()) / frame.height(), toSun, state.shadows, reach, aroundCamera);
    if (!shadows_->cascades().empty()) {
        auto pass = profiler_.scope("Shadow cascades");
        shadows_->render(frame.context, [&](ID3D11Buffer* caster) { terrain.renderDepth(frame.context, frame.shaders, caster); });
    }
    auto pass = profiler_.scope("Terrain");
    for (const GroundLighting& lighting : atmosphere_->groundLighting(frame, state.atmosphere))
        terrain.render(frame, lighting, shadows_->inputs(), clouds_->shadows(), state.terrain);
}

// "Shafts from clouds: shadow map": the clouds hand their shadows to the light shafts through the
// cascades, drawn into each cascade drawn this frame as one more caster.
void Renderer::drawCloudsIntoCascades(FrameContext& frame) {
    if (shadows_->cascades().empty()) return;
    auto pass = profiler_.scope("Clouds: shadows into the cascades");
    shadows_->addCasters(frame.context, [&](ID3D11Buffer*, size_t cascade) {
        clouds_->shadowMap().drawIntoCascade(frame, shadows_->cascades()[cascade].worldToClip);
    });
}

Camera Renderer::viewCamera(const State& state) {
    double highest = 0.0;  // the orientation grid's ground
    if (state.terrain.enabled) highest = std::max(highest, terrain().maxAltitude());
    if (state.clouds.enabled || state.clouds.showParticles != ParticleView::Off)  // the particles, shaded or shown
        highest = std::max(highest, static_cast<double>(state.clouds.altitude + state.clouds.thickness));
    return withFittedNearPlane(state.camera, highest);
}

gpu::FrameConstants Renderer::frameConstants(const State& state, const Camera& camera, FrameTime time) const {
    const float width = static_cast<float>(targets_.width()), height = static_cast<float>(targets_.height());
    const glm::mat4 projection = camera.projection(width / height);
    const glm::mat4 viewProjection = projection * camera.view();
    glm::mat4 rotationOnly = camera.view();
    rotationOnly[3] = glm::vec4(0.0f, 0.0f, 0.0f, 1.0f);
    gpu::FrameConstants c{};
    c.viewProjection = viewProjection;
    c.inverseViewProjection = glm::inverse(viewProjection);
    c.clipToDirection = glm::inverse(projection * rotationOnly);
    c.cameraPosition = glm::vec4(camera.position, camera.position.y);
    c.directionToSun = glm::vec4(state.sun.direction(), 0.0f);
    c.screen = glm::vec4(width, height, 1.0f / width, 1.0f / height);
    c.time = glm::vec4(static_cast<float>(time.seconds), 0.0f, 0.0f, 0.0f);
    c.sunIrradiance = glm::vec4(glm::vec3(state.atmosphere.sunIntensity), 0.0f);
    const ClipmapExtent terrain = clipmapExtent(glm::dvec2(camera.position.x, camera.position.z));
    c.planet = glm::vec4(static_cast<float>(AtmosphereParameters{}.earthRadius), state.terrain.enabled ? static_cast<float>(terrain.halfWidth) : 0.0f,
                         static_cast<float>(terrain.centre.x), static_cast<float>(terrain.centre.y));
    return c;
}

// The light shafts march through Yusov 2013's tables: with his model alone (not Bruneton's, nor
// a comparison of the two), once the tables exist.
bool Renderer::lightShaftsDrawn(const State& state) const {
    const AtmosphereSettings& a = state.atmosphere;
    return state.lightShafts.enabled && a.model == AtmosphereModel::Yusov2013 && a.comparison == ModelComparison::None &&
           atmosphere_->ready(a);
}

Terrain& Renderer::terrain() {
    if (!terrain_)
        terrain_ = std::make_unique<Terrain>(device_, loadOrGenerateHeightField(TerrainGeneratorParameters{}, tables_.cacheFolder),
                                             AtmosphereParameters{}.earthRadius);
    return *terrain_;
}

double Renderer::groundY(double x, double z) { return terrain().groundY(x, z); }

RendererStatus Renderer::status(const State& state) {
    return {toneMapping_->latestReading(context_, state.toneMapping), atmosphere_->recomputeProgress(), clouds_->tableProgress(),
            clouds_->blendingStatus()};
}

std::vector<TableTiming> Renderer::timeTables(const State& state, const std::filesystem::path& scratch) {
    std::vector<TableTiming> timings = atmosphere_->timeTables(context_, shaders_, state.atmosphere, scratch);
    if (state.clouds.enabled || state.clouds.showParticles == ParticleView::OpticalDepth)
        timings.push_back(clouds_->timeTables(device_, context_, shaders_, state.clouds, scratch));
    return timings;
}

std::vector<std::pair<std::string, double>> Renderer::counts(const State& state) {
    if (!state.clouds.enabled && state.clouds.showParticles == ParticleView::Off) return {};
    return clouds_->counts(device_, context_);
}

ExrAttributes Renderer::captureAttributes(const State& state) {
    ExrAttributes a = toneMapping_->captureAttributes(device_, context_, state.toneMapping);
    a.merge(atmosphere_->captureAttributes(state.atmosphere));
    return a;
}

}  // namespace firmament
