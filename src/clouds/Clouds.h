#pragma once
// The clouds (Yusov 2014; docs/clouds.md): the particles' tables, pre-computed and cached, and
// the particles generated and sorted on the GPU each frame, with the views of them that
// "Show particles" selects. The renderer's one entry point for the clouds.
#include "clouds/CloudParticles.h"
#include "clouds/CloudReference.h"
#include "clouds/CloudShadowMap.h"
#include "clouds/LowResolution.h"
#include "clouds/ParticleOpacity.h"
#include "clouds/DeckDiffusionTable.h"
#include "clouds/ParticleScattering.h"
#include "clouds/ParticleTables.h"
#include "clouds/VolumeBlendingPass.h"
#include "frame/BrunetonLookup.h"
#include "frame/HillaireLookup.h"
#include "frame/ScatteringLookup.h"
#include "tables/CachedTables.h"
#include "tables/TableTiming.h"

#include <d3d11.h>

namespace firmament {

struct FrameContext;

class Clouds {
public:
    Clouds(ID3D11Device* device, const TableStorage& storage);

    // Before the terrain: this frame's particles and tables, each particle's light occlusion, and
    // the clouds' shadow map (shadows() and mergeShadowsInto(), read by the terrain and the light
    // shafts). Nothing with the clouds off and Show particles off.
    void update(FrameContext& frame, const CloudSettings& settings);
    // After the terrain: the views drawn as geometry (the bounding shapes, which then take the
    // aerial perspective like the terrain). Nothing when Show particles is off.
    void renderGeometry(FrameContext& frame, const CloudSettings& settings);
    // The clouds' shadow map, applied by its readers when this frame's clouds drew it (shaded
    // clouds, whatever the atmosphere: the particles cast shadows even where they are not lit).
    CloudShadowInputs shadows() const { return shadowMap_.inputs(); }
    const CloudShadowMap& shadowMap() const { return shadowMap_; }
    CloudShadowMap& shadowMap() { return shadowMap_; }
    // The atmosphere model the clouds are lit through: Yusov 2013's tables, Bruneton's or
    // Hillaire's (one of them, the model drawn alone; none in a comparison).
    struct AtmosphereTables {
        const ScatteringLookup* yusov = nullptr;
        const BrunetonLookup* bruneton = nullptr;
        const HillaireLookup* hillaire = nullptr;
    };
    // After the sky and the aerial perspective: the shaded clouds through `atmosphere`, or the
    // translucent view of the particles, over the lit scene. The particle scattering table is
    // read from the storage's media folder the first time; throws Error naming the file when it
    // cannot be.
    void renderTranslucent(FrameContext& frame, const CloudSettings& settings, AtmosphereTables atmosphere);

    CloudParticles& particles() { return particles_; }
    const CloudReference& reference() const { return reference_; }
    const ParticleOpacity& opacity() const { return opacity_; }
    // 0..1 while the particle tables are computed over frames.
    std::optional<double> tableProgress() const;

    static ParticleTableParameters tableParameters(const CloudSettings& settings);
    // The benchmark's records: the particle tables computed against loaded from a cache in
    // `scratch`; the last frame's valid cells, particles and particles over the capacity.
    TableTiming timeTables(ID3D11Device* device, ID3D11DeviceContext* context, ShaderLibrary& shaders, const CloudSettings& settings,
                           const std::filesystem::path& scratch);
    std::vector<std::pair<std::string, double>> counts(ID3D11Device* device, ID3D11DeviceContext* context);
    // The blending the last shaded frame used and, for the lists, their counts a few frames late
    // (the GUI).
    std::string blendingStatus() const;
    // The blending the last shaded frame used, and the device's support for the ordered path.
    ParticleBlending blending() const { return blending_.path(); }
    BlendingSupport blendingSupport() const { return blendingSupport_; }

private:
    void updateTables(FrameContext& frame, const CloudSettings& settings, bool finishNow);
    void drawOpticalDepth(FrameContext& frame, const ParticleTables& tables);
    void drawShaded(FrameContext& frame, const ParticleTables& tables, AtmosphereTables atmosphere, ParticleBlending blending, const CloudSettings& settings);
    // Renderer: Reference (path traced): the paths added and their mean over the frame.
    void drawReference(FrameContext& frame, const CloudSettings& settings, AtmosphereTables atmosphere);
    const Texture3D& scatteringTable(ID3D11Device* device);
    const Texture3D& deckDiffusionTable(ID3D11Device* device);

    TableStorage storage_;
    CachedTables<ParticleTablePrecomputation> tables_;
    CloudParticles particles_;
    ComPtr<ID3D11SamplerState> linearWrap_;
    ComPtr<ID3D11BlendState> premultiplied_;
    ComPtr<ID3D11RasterizerState> noCulling_;
    ConstantBuffer<gpu::CloudShadingConstants> shadingConstants_;
    ParticleScatteringParameters scatteringParameters_;
    Texture3D scattering_;  // R32G32B32A32_FLOAT: single scattering (phase excluded), multiple, the forward peak's (phase excluded)
    DeckDiffusionParameters deckParameters_;
    Texture3D deckDiffusion_;  // R32_FLOAT: deck diffusion's light scattered more than once (cosine, depth, thickness); read when first chosen
    BlendingSupport blendingSupport_;
    VolumeBlendingPass blending_;
    CloudLowResolution lowResolution_;
    ParticleOpacity opacity_;
    CloudShadowMap shadowMap_;
    CloudReference reference_;
    // The reference traces the particles of the moment it was chosen: their clock stands still
    // while it is on, so that its paths can accumulate.
    std::optional<double> referenceSeconds_;
    bool referenceDrawn_ = false;
};

}  // namespace firmament
