#include "clouds/Clouds.h"

#include "gpu/CommonStates.h"
#include "render/FrameContext.h"

namespace firmament {

namespace {
const ShaderKey kOpticalDepthVertexShader{"clouds/optical_depth_view.hlsl", "vs_main", "vs_5_0", {}};
const ShaderKey kOpticalDepthPixelShader{"clouds/optical_depth_view.hlsl", "ps_main", "ps_5_0", {}};
}  // namespace

Clouds::Clouds(ID3D11Device* device, const TableStorage& storage)
    : storage_(storage),
      tables_("clouds", "Clouds: particle tables"),
      particles_(device),
      linearWrap_(states::linearWrap(device)),
      premultiplied_(states::premultipliedAlpha(device)),
      noCulling_(states::cullNone(device)) {}

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

const ParticleTablePrecomputation& Clouds::tables(FrameContext& frame, const CloudSettings& settings) {
    updateTables(frame, settings, true);
    return *tables_.current();
}

std::optional<double> Clouds::tableProgress() const {
    if (const ParticleTablePrecomputation* pending = tables_.pending()) return pending->progress();
    return std::nullopt;
}

void Clouds::renderGeometry(FrameContext& frame, const CloudSettings& settings) {
    if (settings.showParticles == ParticleView::Off) return;
    const OpticalDepthTableSize& n = tableParameters(settings).opticalDepth;
    particles_.update(frame, settings,
                      glm::vec4(static_cast<float>(n.entryZenith), static_cast<float>(n.entryAzimuth), static_cast<float>(n.directionZenith),
                                static_cast<float>(n.directionAzimuth)));
    if (settings.showParticles == ParticleView::BoundingShapes) particles_.drawBoundingShapes(frame);
    else updateTables(frame, settings, frame.finishWorkNow);
}

void Clouds::renderTranslucent(FrameContext& frame, const CloudSettings& settings) {
    if (settings.showParticles != ParticleView::OpticalDepth) return;
    if (const ParticleTablePrecomputation* tables = tables_.current()) drawOpticalDepth(frame, tables->tables());
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
    particles_.drawInstanced(frame, kOpticalDepthVertexShader, kOpticalDepthPixelShader);
    ID3D11ShaderResourceView* none[2] = {};
    context->PSSetShaderResources(2, 2, none);
    context->OMSetBlendState(nullptr, nullptr, 0xffffffffu);
}

}  // namespace firmament
