#include "clouds/CloudShadowMap.h"

#include "clouds/CloudParticles.h"
#include "clouds/LightSpace.h"
#include "clouds/ParticleTables.h"
#include "frame/FrameContext.h"
#include "gpu/CommonStates.h"
#include "gpu/Hresult.h"

#include <glm/geometric.hpp>
#include <glm/matrix.hpp>

#include <algorithm>
#include <cmath>

namespace firmament {

namespace {
const ShaderKey kMapVertexShader{"clouds/cloud_shadow_map.hlsl", "vs_main", "vs_5_0", {}};
const ShaderKey kMapPixelShader{"clouds/cloud_shadow_map.hlsl", "ps_main", "ps_5_0", {}};
const ShaderKey kMergeVertexShader{"clouds/merge_cloud_shadows.hlsl", "vs_main", "vs_5_0", {}};
const ShaderKey kMergePixelShader{"clouds/merge_cloud_shadows.hlsl", "ps_main", "ps_5_0", {}};
// No cloud on a ray: no stretch (the blend keeps the smallest extents) and full transmittance.
constexpr float kEmpty[4] = {3.0e38f, 3.0e38f, 0.0f, 1.0f};
}  // namespace

CloudShadowMap::CloudShadowMap(ID3D11Device* device)
    : constantsBuffer_(device),
      writerBuffer_(device),
      mergeBuffer_(device),
      blend_(states::minimumColourProductAlpha(device)),
      noCulling_(states::cullNone(device)),
      linearWrap_(states::linearWrap(device)) {
    D3D11_TEXTURE2D_DESC desc{};
    desc.Width = desc.Height = kResolution;
    desc.MipLevels = 1;
    desc.ArraySize = 2;
    desc.Format = DXGI_FORMAT_R32G32B32A32_FLOAT;
    desc.SampleDesc.Count = 1;
    desc.Usage = D3D11_USAGE_DEFAULT;
    desc.BindFlags = D3D11_BIND_RENDER_TARGET | D3D11_BIND_SHADER_RESOURCE;
    check(device->CreateTexture2D(&desc, nullptr, &maps_), "CreateTexture2D (cloud shadow maps)");
    check(device->CreateShaderResourceView(maps_.Get(), nullptr, &srv_), "CreateShaderResourceView (cloud shadow maps)");
    for (UINT slice = 0; slice < 2; ++slice) {
        D3D11_RENDER_TARGET_VIEW_DESC view{};
        view.Format = desc.Format;
        view.ViewDimension = D3D11_RTV_DIMENSION_TEXTURE2DARRAY;
        view.Texture2DArray.FirstArraySlice = slice;
        view.Texture2DArray.ArraySize = 1;
        check(device->CreateRenderTargetView(maps_.Get(), &view, &slices_[slice]), "CreateRenderTargetView (cloud shadow map)");
    }
}

double CloudShadowMap::farHalfWidth(const CloudSettings& settings) {
    return std::max(static_cast<double>(settings.particleDistance) * std::sqrt(2.0) + settings.altitude + settings.thickness, 2.0 * kHalfWidth);
}

gpu::CloudShadowConstants CloudShadowMap::constants(glm::dvec3 camera, glm::dvec3 toSun, bool active, double farHalfWidth, int resolution,
                                                    double halfWidth) {
    const auto [right, up, sun] = sunFrame(toSun);
    const auto centreFor = [&](double width) {
        const double texel = 2.0 * width / resolution;
        return right * (std::floor(glm::dot(camera, right) / texel) * texel) + up * (std::floor(glm::dot(camera, up) / texel) * texel) +
               sun * glm::dot(camera, sun);
    };
    gpu::CloudShadowConstants c{};
    c.centre = glm::vec4(glm::vec3(centreFor(halfWidth)), static_cast<float>(halfWidth));
    c.farCentre = glm::vec4(glm::vec3(centreFor(farHalfWidth)), static_cast<float>(farHalfWidth));
    c.right = glm::vec4(glm::vec3(right), static_cast<float>(resolution));
    c.up = glm::vec4(glm::vec3(up), active ? 1.0f : 0.0f);
    c.sun = glm::vec4(glm::vec3(sun), static_cast<float>(kEdgeFade));
    return c;
}

void CloudShadowMap::clear(ID3D11DeviceContext* context) {
    constants_.up.w = 0.0f;
    constantsBuffer_.update(context, constants_);
}

void CloudShadowMap::render(FrameContext& frame, CloudParticles& particles, const ParticleTables& tables, const CloudSettings& settings) {
    ID3D11DeviceContext* context = frame.context;
    auto pass = frame.profiler.scope("Clouds: shadow maps");
    const glm::vec4 camera = frame.constants.cameraPosition, sun = frame.constants.directionToSun;
    constants_ = constants(glm::dvec3(camera.x, camera.y, camera.z), glm::dvec3(sun.x, sun.y, sun.z), true, farHalfWidth(settings));
    constantsBuffer_.update(context, constants_);
    for (int slice = 0; slice < 2; ++slice) {
        // The writer sees each map as the near one.
        gpu::CloudShadowConstants own = constants_;
        if (slice == 1) own.centre = constants_.farCentre;
        writerBuffer_.update(context, own);
        context->ClearRenderTargetView(slices_[slice].Get(), kEmpty);
        ID3D11RenderTargetView* target = slices_[slice].Get();
        context->OMSetRenderTargets(1, &target, nullptr);
        context->OMSetBlendState(blend_.Get(), nullptr, 0xffffffffu);
        context->OMSetDepthStencilState(nullptr, 0);
        context->RSSetState(noCulling_.Get());
        ID3D11Buffer* buffer = writerBuffer_.get();
        context->VSSetConstantBuffers(2, 1, &buffer);
        context->PSSetConstantBuffers(2, 1, &buffer);
        context->PSSetShaderResources(2, 1, tables.opticalDepth.srv.GetAddressOf());
        context->PSSetSamplers(0, 1, linearWrap_.GetAddressOf());
        particles.drawInstanced(frame, kMapVertexShader, kMapPixelShader, ParticleSet::All, kResolution, kResolution);
    }
    ID3D11ShaderResourceView* none = nullptr;
    context->PSSetShaderResources(2, 1, &none);
    context->OMSetRenderTargets(0, nullptr, nullptr);
    context->OMSetBlendState(nullptr, nullptr, 0xffffffffu);
}

void CloudShadowMap::drawIntoCascade(FrameContext& frame, const glm::dmat4& cascadeWorldToClip) {
    ID3D11DeviceContext* context = frame.context;
    mergeBuffer_.update(context, gpu::CloudShadowMergeConstants{glm::mat4(glm::inverse(cascadeWorldToClip)), glm::mat4(cascadeWorldToClip)});
    ID3D11Buffer* buffers[] = {constantsBuffer_.get(), mergeBuffer_.get()};
    context->PSSetConstantBuffers(0, 2, buffers);
    context->PSSetShaderResources(0, 1, srv_.GetAddressOf());
    context->IASetInputLayout(nullptr);
    context->IASetPrimitiveTopology(D3D11_PRIMITIVE_TOPOLOGY_TRIANGLELIST);
    context->VSSetShader(frame.shaders.vertexShader(kMergeVertexShader), nullptr, 0);
    context->PSSetShader(frame.shaders.pixelShader(kMergePixelShader), nullptr, 0);
    context->Draw(3, 0);
    ID3D11ShaderResourceView* none = nullptr;
    context->PSSetShaderResources(0, 1, &none);
}

}  // namespace firmament
