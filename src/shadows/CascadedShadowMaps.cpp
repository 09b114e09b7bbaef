#include "shadows/CascadedShadowMaps.h"

#include "gpu/CommonStates.h"
#include "gpu/Hresult.h"

#include <algorithm>

#include <cmath>

namespace firmament {

namespace {
constexpr float kNormalOffsetTexels = 1.5f;  // receivers pushed along their normal (against acne)
constexpr float kSlopeScaledBias = 2.0f;      // casters pushed away by their depth slope
}  // namespace

CascadedShadowMaps::CascadedShadowMaps(ID3D11Device* device)
    : device_(device),
      comparison_(states::shadowComparison(device)),
      casterRaster_(states::shadowCaster(device, kSlopeScaledBias)),  // casters nearer the sun than the range clamp to depth 0 and still cast
      casterDepth_(states::depthLess(device)),
      constantBuffer_(device),
      casterBuffer_(device) {}

// The atlas: up to four cascades to a row. One texture, not an array: Wine's Direct3D compares
// against slice 0 whatever the array index (docs/shadows.md), and an atlas is as fast.
void CascadedShadowMaps::createMap(int resolution, int cascades) {
    columns_ = std::min(cascades, kAtlasColumns);
    rows_ = (cascades + kAtlasColumns - 1) / kAtlasColumns;
    D3D11_TEXTURE2D_DESC desc{};
    desc.Width = static_cast<UINT>(resolution * columns_);
    desc.Height = static_cast<UINT>(resolution * rows_);
    desc.MipLevels = 1;
    desc.ArraySize = 1;
    desc.Format = DXGI_FORMAT_R32_TYPELESS;
    desc.SampleDesc.Count = 1;
    desc.Usage = D3D11_USAGE_DEFAULT;
    desc.BindFlags = D3D11_BIND_DEPTH_STENCIL | D3D11_BIND_SHADER_RESOURCE;
    map_.Reset();
    dsv_.Reset();
    srv_.Reset();
    check(device_->CreateTexture2D(&desc, nullptr, &map_), "CreateTexture2D (shadow map atlas, " + std::to_string(cascades) +
                                                                    " cascades of " + std::to_string(resolution) + " x " + std::to_string(resolution) + ")");
    D3D11_DEPTH_STENCIL_VIEW_DESC dsv{};
    dsv.Format = DXGI_FORMAT_D32_FLOAT;
    dsv.ViewDimension = D3D11_DSV_DIMENSION_TEXTURE2D;
    check(device_->CreateDepthStencilView(map_.Get(), &dsv, &dsv_), "CreateDepthStencilView (shadow map atlas)");
    D3D11_SHADER_RESOURCE_VIEW_DESC srv{};
    srv.Format = DXGI_FORMAT_R32_FLOAT;
    srv.ViewDimension = D3D11_SRV_DIMENSION_TEXTURE2D;
    srv.Texture2D.MipLevels = 1;
    check(device_->CreateShaderResourceView(map_.Get(), &srv, &srv_), "CreateShaderResourceView (shadow map atlas)");
    resolution_ = resolution;
    cascadeCount_ = cascades;
}

void CascadedShadowMaps::update(ID3D11DeviceContext* context, const Camera& camera, double aspectRatio, glm::dvec3 directionToSun,
                                const ShadowSettings& settings, double casterReach, int cascadeAroundCamera) {
    cascades_.clear();
    constants_ = {};
    if (settings.enabled) {
        const int count = std::clamp(settings.cascades, 1, kMaxCascades);
        const int resolution = shadowMapTexels(settings.resolution);
        if (resolution != resolution_ || count != cascadeCount_) createMap(resolution, count);
        CascadeCamera view;
        view.position = camera.position;
        view.forward = camera.forward();
        view.tanHalfFovY = std::tan(glm::radians(static_cast<double>(camera.verticalFovDegrees)) * 0.5);
        view.aspectRatio = aspectRatio;
        const double reach = std::min(static_cast<double>(settings.distanceKm) * 1000.0, static_cast<double>(camera.farPlane));
        const std::vector<double> splits = cascadeSplits(camera.nearPlane, reach, count, settings.partitioningFactor);
        const glm::dmat4 lightView = lightViewMatrix(directionToSun);
        for (int i = 0; i < count; ++i) {
            cascades_.push_back(fitCascade(view, splits[static_cast<size_t>(i)], splits[static_cast<size_t>(i) + 1], lightView, resolution, casterReach,
                                           i == cascadeAroundCamera));
            constants_.worldToShadow[i] = glm::mat4(cascades_.back().worldToShadow);
            constants_.texelWorldSize[i / 4][i % 4] = static_cast<float>(cascades_.back().texelWorldSize);
        }
        for (int i = 0; i <= count; ++i) constants_.splits[i / 4][i % 4] = static_cast<float>(splits[static_cast<size_t>(i)]);
        constants_.cameraForward = glm::vec4(glm::vec3(view.forward), 0.0f);
        constants_.mode = glm::uvec4(static_cast<unsigned>(count), settings.smoothShadows ? 1u : 0u, settings.bestCascadeSearch ? 1u : 0u,
                                     settings.showCascades ? 1u : 0u);
        constants_.map = glm::vec4(static_cast<float>(resolution), 1.0f / static_cast<float>(resolution), 0.0f, kNormalOffsetTexels);
        constants_.atlas = glm::vec4(static_cast<float>(columns_), static_cast<float>(rows_), 1.0f / static_cast<float>(columns_),
                                     1.0f / static_cast<float>(rows_));
    }
    constantBuffer_.update(context, constants_);
}

void CascadedShadowMaps::render(ID3D11DeviceContext* context, const std::function<void(ID3D11Buffer* caster)>& drawCasters) {
    drawCascades(context, true, [&](ID3D11Buffer* caster, size_t) { drawCasters(caster); });
}

void CascadedShadowMaps::addCasters(ID3D11DeviceContext* context, const std::function<void(ID3D11Buffer* caster, size_t cascade)>& drawCasters) {
    drawCascades(context, false, drawCasters);
}

void CascadedShadowMaps::drawCascades(ID3D11DeviceContext* context, bool clear,
                                      const std::function<void(ID3D11Buffer* caster, size_t cascade)>& drawCasters) {
    if (cascades_.empty()) return;
    context->RSSetState(casterRaster_.Get());
    context->OMSetDepthStencilState(casterDepth_.Get(), 0);
    if (clear) context->ClearDepthStencilView(dsv_.Get(), D3D11_CLEAR_DEPTH, 1.0f, 0);
    context->OMSetRenderTargets(0, nullptr, dsv_.Get());
    for (size_t i = 0; i < cascades_.size(); ++i) {
        // The cascade's tile; clipping to the clip volume keeps each cascade inside its own.
        const float size = static_cast<float>(resolution_);
        D3D11_VIEWPORT viewport{size * static_cast<float>(i % kAtlasColumns), size * static_cast<float>(i / kAtlasColumns), size, size, 0.0f, 1.0f};
        context->RSSetViewports(1, &viewport);
        casterBuffer_.update(context, gpu::ShadowCasterConstants{glm::mat4(cascades_[i].worldToClip)});
        drawCasters(casterBuffer_.get(), i);
    }
    context->OMSetRenderTargets(0, nullptr, nullptr);
    context->RSSetState(nullptr);
    context->OMSetDepthStencilState(nullptr, 0);
}

ShadowInputs CascadedShadowMaps::inputs() const {
    return {constantBuffer_.get(), cascades_.empty() ? nullptr : srv_.Get(), comparison_.Get(), cascades_.empty() ? 0 : resolution_,
            static_cast<int>(cascades_.size())};
}

}  // namespace firmament
