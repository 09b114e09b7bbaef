#pragma once
// The atmosphere technique: the look-up tables for the current physical parameters, and the
// sky, the sun and the aerial perspective drawn with them, by Yusov 2013's model, Bruneton and
// Neyret 2008's or Hillaire 2020's, or several to compare them (ModelRegions.h: two side by
// side, their difference, or all three in thirds).
//  - Update step: when a setting that shapes the tables changes, new tables are made (from the
//    cache, or computed one unit of work per frame while the old ones stay in use; at once when
//    the frame says so). Until the first tables exist, ready() is false and the program shows
//    the orientation grid's own sky.
//  - Render steps: the sky where nothing was drawn, and the aerial perspective over geometry,
//    two passes so that the light shafts can replace the second.
//  - Hand-offs: the tables that light the ground (GroundLighting, per region of the frame), and
//    each model's tables for a technique that looks them up itself (ScatteringLookup,
//    BrunetonLookup, HillaireLookup).
// The model comparison stays inside: the ground sees only the regions it is given.
#include "atmosphere/AtmosphereSettings.h"
#include "atmosphere/ModelRegions.h"
#include "atmosphere/bruneton/BrunetonPass.h"
#include "atmosphere/hillaire/HillairePass.h"
#include "atmosphere/yusov/YusovPass.h"
#include "core/ExrImage.h"
#include "frame/BrunetonLookup.h"
#include "frame/FrameContext.h"
#include "frame/GroundLighting.h"
#include "frame/HillaireLookup.h"
#include "frame/ScatteringLookup.h"
#include "tables/CachedTables.h"
#include "tables/TableTiming.h"

#include <optional>
#include <vector>

namespace firmament {

class Atmosphere {
public:
    Atmosphere(ID3D11Device* device, TableStorage storage);

    // Frame order step 1: the tables for these settings. Their work is timed as
    // "Atmosphere tables (Yusov)", "(Bruneton)" and "(Hillaire)".
    void update(FrameContext& frame, const AtmosphereSettings& settings);
    // The tables the settings' model (or both, to compare) need exist.
    bool ready(const AtmosphereSettings& settings) const;

    // Where nothing was drawn: the sky, the sun's disc and, for Bruneton's model, its ground.
    // Hillaire's model first makes its sky-view table and aerial-perspective volume for the frame
    // (timed as "Sky-view and aerial perspective (Hillaire)").
    void renderSky(FrameContext& frame, const AtmosphereSettings& settings);
    // Over geometry: its radiance through the atmosphere and the light scattered in between.
    void renderAerialPerspective(FrameContext& frame, const AtmosphereSettings& settings);

    // The tables that light the ground, one entry per region of the frame: none of the models'
    // (GroundLightingModel::None) when the atmosphere is off or not ready; in a split or three-way
    // view each model's over its columns; in the difference view the first model's.
    std::vector<GroundLighting> groundLighting(FrameContext& frame, const AtmosphereSettings& settings);
    // Yusov's tables for another technique; not ready() when that model's tables do not exist.
    ScatteringLookup scatteringLookup(FrameContext& frame, const AtmosphereSettings& settings);
    // Bruneton's tables for another technique; not ready() when that model's tables do not exist.
    BrunetonLookup brunetonLookup(FrameContext& frame, const AtmosphereSettings& settings);
    // Hillaire's tables for another technique; not ready() when that model's tables do not exist.
    HillaireLookup hillaireLookup(FrameContext& frame, const AtmosphereSettings& settings);

    // For each model the settings draw: how long its tables take to compute, and to load from a
    // cache written into `scratch` (the benchmark). Does not touch the tables in use.
    std::vector<TableTiming> timeTables(ID3D11DeviceContext* context, ShaderLibrary& shaders, const AtmosphereSettings& settings,
                                        const std::filesystem::path& scratch);

    // 0..1 while new tables are computed, nullopt otherwise.
    std::optional<double> recomputeProgress() const;
    // "firmament.atmosphere.*": the physical constants of the tables in use, the model drawn.
    ExrAttributes captureAttributes(const AtmosphereSettings& settings) const;

private:
    void render(FrameContext& frame, const AtmosphereSettings& settings, AtmospherePart part);
    void drawModel(FrameContext& frame, const AtmosphereSettings& settings, AtmospherePart part, const ModelRegion& region,
                   ID3D11ShaderResourceView* scene);
    GroundLighting groundLightingOf(FrameContext& frame, const ModelRegion& region);

    ID3D11Device* device_;
    TableStorage storage_;
    CachedTables<YusovPrecomputation> yusov_;
    CachedTables<BrunetonPrecomputation> bruneton_;
    CachedTables<HillairePrecomputation> hillaire_;
    YusovPass yusovPass_;
    BrunetonPass brunetonPass_;
    HillairePass hillairePass_;
    ConstantBuffer<gpu::AtmosphereConstants> yusovConstants_;  // the hand-offs' copies of the models' constants
    ConstantBuffer<gpu::AtmosphereConstants> brunetonPhysics_;
    ConstantBuffer<gpu::BrunetonConstants> brunetonConstants_;
    ConstantBuffer<gpu::AtmosphereConstants> hillairePhysics_;
    ConstantBuffer<gpu::HillaireConstants> hillaireConstants_;
    ComPtr<ID3D11SamplerState> linearClamp_;
    FullscreenPass difference_;
    Texture2D firstModel_, secondModel_;  // the difference view: the frame as each model drew it
};

}  // namespace firmament
