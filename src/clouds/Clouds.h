#pragma once
// The clouds (Yusov 2014; docs/clouds.md): the particles' tables, pre-computed and cached, and
// the particles generated and sorted on the GPU each frame, with the views of them that
// "Show particles" selects. The renderer's one entry point for the clouds.
#include "clouds/CloudParticles.h"
#include "clouds/ParticleTables.h"
#include "tables/CachedTables.h"

#include <d3d11.h>

namespace firmament {

struct FrameContext;

class Clouds {
public:
    Clouds(ID3D11Device* device, const TableStorage& storage);

    // After the terrain: this frame's particles and tables, and the views drawn as geometry (the
    // bounding shapes, which then take the aerial perspective like the terrain). Nothing when
    // Show particles is off.
    void renderGeometry(FrameContext& frame, const CloudSettings& settings);
    // After the sky and the aerial perspective: the translucent views over the lit scene.
    void renderTranslucent(FrameContext& frame, const CloudSettings& settings);

    // The particle tables for `settings`, computed or loaded now (tests, benchmarks).
    const ParticleTablePrecomputation& tables(FrameContext& frame, const CloudSettings& settings);
    CloudParticles& particles() { return particles_; }
    // 0..1 while the particle tables are computed over frames.
    std::optional<double> tableProgress() const;

    static ParticleTableParameters tableParameters(const CloudSettings& settings);

private:
    void updateTables(FrameContext& frame, const CloudSettings& settings, bool finishNow);
    void drawOpticalDepth(FrameContext& frame, const ParticleTables& tables);

    TableStorage storage_;
    CachedTables<ParticleTablePrecomputation> tables_;
    CloudParticles particles_;
    ComPtr<ID3D11SamplerState> linearWrap_;
    ComPtr<ID3D11BlendState> premultiplied_;
    ComPtr<ID3D11RasterizerState> noCulling_;
};

}  // namespace firmament
