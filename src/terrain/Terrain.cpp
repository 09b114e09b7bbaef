#include "terrain/Terrain.h"

#include "gpu/CommonStates.h"
#include "gpu/Hresult.h"
#include "terrain/TerrainSurface.h"

#include <algorithm>
#include <string>

namespace firmament {

namespace {

const ShaderKey kVertexShader{"terrain/terrain.hlsl", "vs_main", "vs_5_0", {}};
const ShaderKey kDepthVertexShader{"terrain/terrain.hlsl", "vs_depth", "vs_5_0", {}};
ShaderKey pixelShader(GroundLightingModel model) {
    return {"terrain/terrain.hlsl", "ps_main", "ps_5_0", {"GROUND_LIGHTING=" + std::to_string(static_cast<int>(model))}};
}

// A square texture with a full mip chain from `mips` (mip m of size >> m texels a side),
// readable by shaders.
template <typename Texel>
Texture2D createMipmappedTexture(ID3D11Device* device, DXGI_FORMAT format, int size, const std::vector<std::vector<Texel>>& mips) {
    D3D11_TEXTURE2D_DESC desc{};
    desc.Width = desc.Height = static_cast<UINT>(size);
    desc.MipLevels = static_cast<UINT>(mips.size());
    desc.ArraySize = 1;
    desc.Format = format;
    desc.SampleDesc.Count = 1;
    desc.Usage = D3D11_USAGE_IMMUTABLE;
    desc.BindFlags = D3D11_BIND_SHADER_RESOURCE;
    std::vector<D3D11_SUBRESOURCE_DATA> data(mips.size());
    for (size_t m = 0; m < mips.size(); ++m)
        data[m] = {mips[m].data(), static_cast<UINT>(sizeof(Texel) * static_cast<size_t>(size >> m)), 0};
    Texture2D t;
    check(device->CreateTexture2D(&desc, data.data(), &t.texture), "CreateTexture2D (terrain height field)");
    check(device->CreateShaderResourceView(t.texture.Get(), nullptr, &t.srv), "CreateShaderResourceView (terrain height field)");
    t.width = t.height = size;
    t.format = format;
    return t;
}

}  // namespace

Terrain::Terrain(ID3D11Device* device, HeightField field, double earthRadius)
    : field_(std::move(field)),
      earthRadius_(earthRadius),
      mesh_(device),
      constants_(device),
      linearClamp_(states::linearClamp(device)),
      linearWrap_(states::linearWrap(device)),
      solid_(states::cullBackScissored(device)),
      depthTest_(states::depthReversed(device)) {
    std::vector<std::vector<float>> heightMips;
    std::vector<std::vector<glm::vec2>> slopeMips;
    for (int m = 0; m < field_.mipCount(); ++m) {
        heightMips.push_back(field_.heights(m));
        slopeMips.push_back(field_.slopes(m));
    }
    heights_ = createMipmappedTexture(device, DXGI_FORMAT_R32_FLOAT, field_.size(), heightMips);
    slopes_ = createMipmappedTexture(device, DXGI_FORMAT_R32G32_FLOAT, field_.size(), slopeMips);
    slopeMoments_ = createMipmappedTexture(device, DXGI_FORMAT_R32_FLOAT, field_.size(), field_.slopeSecondMoments());
}

double Terrain::groundHeight(double x, double z) const { return surfaceHeight(field_, x, z, kFinestSpacing); }

double Terrain::groundY(double x, double z) const { return groundHeight(x, z) - earthDrop(x, z, earthRadius_); }

void Terrain::place(glm::dvec3 camera) {
    const double altitude = camera.y + earthDrop(camera.x, camera.z, earthRadius_);
    const double aboveGround = std::max(altitude - groundHeight(camera.x, camera.z), 0.0);
    levels_ = clipmapLevels(glm::dvec2(camera.x, camera.z), aboveGround);
}

void Terrain::bindFieldTextures(ID3D11DeviceContext* context, bool pixelStage) {
    ID3D11ShaderResourceView* views[2] = {heights_.srv.Get(), slopes_.srv.Get()};
    context->VSSetShaderResources(0, 1, views);
    if (pixelStage) context->PSSetShaderResources(0, 2, views);
}

// One draw per level, finest first (the nearest ground fills depth first).
void Terrain::drawLevels(ID3D11DeviceContext* context, unsigned view) {
    mesh_.bind(context);
    ID3D11Buffer* terrain = constants_.get();
    context->VSSetConstantBuffers(3, 1, &terrain);
    context->PSSetConstantBuffers(3, 1, &terrain);
    for (size_t k = 0; k < levels_.size(); ++k) {
        const ClipmapLevel& level = levels_[k];
        const bool coarser = k + 1 < levels_.size();
        gpu::TerrainConstants c{};
        c.field = glm::vec4(static_cast<float>(field_.spacing()), static_cast<float>(field_.size()), 1.0f / static_cast<float>(field_.size()),
                            static_cast<float>(earthRadius_));
        c.level = glm::vec4(static_cast<float>(level.origin.x), static_cast<float>(level.origin.y), static_cast<float>(level.spacing),
                            static_cast<float>(heightMipFor(level.spacing, field_)));
        c.coarser = coarser ? glm::vec4(static_cast<float>(2.0 * level.spacing), static_cast<float>(heightMipFor(2.0 * level.spacing, field_)),
                                        static_cast<float>(kClipmapCells / 8), 0.0f)
                            : glm::vec4(0.0f);
        const glm::uvec2 hole = level.hasHole ? glm::uvec2(static_cast<unsigned>(holeFirstCell(level.holeOffset.x)),
                                                           static_cast<unsigned>(holeFirstCell(level.holeOffset.y)))
                                              : glm::uvec2(0xffffu);
        c.grid = glm::uvec4(kClipmapCells, static_cast<unsigned>(level.index), view, hole.x | (hole.y << 16));
        constants_.update(context, c);
        const IndexRange range = level.hasHole ? mesh_.holed(level.holeOffset) : mesh_.whole();
        context->DrawIndexed(range.count, range.first, 0);
    }
}

void Terrain::render(FrameContext& frame, const GroundLighting& lighting, const ShadowInputs& shadows, const CloudShadowInputs& clouds,
                     const TerrainSettings& settings) {
    ID3D11DeviceContext* context = frame.context;
    const int width = frame.width(), height = frame.height();
    D3D11_VIEWPORT viewport{0.0f, 0.0f, static_cast<float>(width), static_cast<float>(height), 0.0f, 1.0f};
    context->RSSetViewports(1, &viewport);
    const D3D11_RECT columns{std::clamp(lighting.firstColumn, 0, width), 0, std::clamp(lighting.endColumn, 0, width), height};
    context->RSSetScissorRects(1, &columns);
    context->RSSetState(solid_.Get());
    ID3D11RenderTargetView* hdrFrame = frame.targets.hdr().rtv.Get();
    context->OMSetRenderTargets(1, &hdrFrame, frame.targets.depth().dsv.Get());
    context->OMSetDepthStencilState(depthTest_.Get(), 0);
    context->OMSetBlendState(nullptr, nullptr, 0xffffffff);
    ID3D11Buffer* buffers[7] = {frame.frameConstants, lighting.atmosphere, lighting.modelConstants, constants_.get(), shadows.constants, nullptr,
                                clouds.constants};
    context->VSSetConstantBuffers(0, 5, buffers);
    context->PSSetConstantBuffers(0, 7, buffers);
    bindFieldTextures(context, true);
    ID3D11ShaderResourceView* tables[5] = {lighting.sunTransmittance, lighting.skyIrradiance, shadows.map, clouds.map, slopeMoments_.srv.Get()};
    context->PSSetShaderResources(2, 5, tables);
    ID3D11SamplerState* samplers[3] = {linearClamp_.Get(), linearWrap_.Get(), shadows.comparison};
    context->PSSetSamplers(0, 3, samplers);
    context->VSSetShader(frame.shaders.vertexShader(kVertexShader), nullptr, 0);
    context->PSSetShader(frame.shaders.pixelShader(pixelShader(lighting.model)), nullptr, 0);
    drawLevels(context, static_cast<unsigned>(settings.view));
    ID3D11ShaderResourceView* none[7] = {};
    context->PSSetShaderResources(0, 7, none);
    context->VSSetShaderResources(0, 2, none);
    context->RSSetState(nullptr);
    context->OMSetDepthStencilState(nullptr, 0);
}

void Terrain::renderDepth(ID3D11DeviceContext* context, ShaderLibrary& shaders, ID3D11Buffer* caster) {
    context->VSSetConstantBuffers(5, 1, &caster);
    bindFieldTextures(context, false);
    context->VSSetShader(shaders.vertexShader(kDepthVertexShader), nullptr, 0);
    context->PSSetShader(nullptr, nullptr, 0);
    drawLevels(context, 0);
    ID3D11ShaderResourceView* none[2] = {};
    context->VSSetShaderResources(0, 2, none);
}

}  // namespace firmament
