#include "atmosphere/hillaire/HillairePass.h"

#include "atmosphere/SunDisc.h"
#include "gpu/CommonStates.h"

namespace firmament {

namespace {
const std::string kShaderFile = "atmosphere/hillaire/render.hlsl";
const ShaderKey kSkyView{"atmosphere/hillaire/sky_view.hlsl", "main", "cs_5_0", {}};
const ShaderKey kAerialPerspective{"atmosphere/hillaire/aerial_perspective.hlsl", "main", "cs_5_0", {}};
constexpr unsigned kGroup = 8;  // both shaders: 8 x 8 x 1
constexpr UINT kReadWrite = D3D11_BIND_SHADER_RESOURCE | D3D11_BIND_UNORDERED_ACCESS;
}  // namespace

HillaireFrameSampling HillaireFrameSampling::from(const AtmosphereSettings& settings) {
    return {settings.hillaireSkyViewWidth, settings.hillaireSkyViewHeight, settings.hillaireSkyViewSteps, settings.hillaireFroxels,
            settings.hillaireFroxelSteps};
}

HillairePass::HillairePass(ID3D11Device* device)
    : device_(device), fullscreen_(device), atmosphere_(device), hillaire_(device), pass_(device), linearClamp_(states::linearClamp(device)) {}

gpu::HillaireConstants HillairePass::constants(const HillaireParameters& parameters, const HillaireFrameSampling& sampling) {
    gpu::HillaireConstants c = parameters.constants();
    c.skyView = glm::vec4(static_cast<float>(sampling.skyViewWidth), static_cast<float>(sampling.skyViewHeight), static_cast<float>(sampling.skyViewSteps),
                          0.0f);
    c.aerialPerspective = glm::vec4(static_cast<float>(sampling.froxels), static_cast<float>(atmosphere::hillaire::kAerialPerspectiveDepth),
                                    static_cast<float>(sampling.froxelSteps), static_cast<float>(sampling.skyViewSteps));
    return c;
}

void HillairePass::makeCameraTables(ID3D11DeviceContext* context, ShaderLibrary& shaders, const HillairePrecomputation& tables,
                                    ID3D11Buffer* frameConstants, const HillaireFrameSampling& sampling) {
    if (camera_.skyView.width != sampling.skyViewWidth || camera_.skyView.height != sampling.skyViewHeight)
        camera_.skyView = createColorTexture(device_, sampling.skyViewWidth, sampling.skyViewHeight, DXGI_FORMAT_R32G32B32A32_FLOAT, kReadWrite);
    if (camera_.aerialInscattering.width != sampling.froxels) {
        const int n = sampling.froxels;
        camera_.aerialInscattering = createTexture3D(device_, n, n, n, DXGI_FORMAT_R32G32B32A32_FLOAT, kReadWrite);
        camera_.aerialTransmittance = createTexture3D(device_, n, n, n, DXGI_FORMAT_R32G32B32A32_FLOAT, kReadWrite);
    }
    atmosphere_.update(context, tables.parameters().physics.constants());
    hillaire_.update(context, constants(tables.parameters(), sampling));
    ID3D11Buffer* buffers[] = {frameConstants, atmosphere_.get(), hillaire_.get()};
    context->CSSetConstantBuffers(0, 3, buffers);
    ID3D11SamplerState* sampler = linearClamp_.Get();
    context->CSSetSamplers(0, 1, &sampler);
    const HillaireTables& t = tables.tables();

    bindCompute(context, shaders.computeShader(kSkyView), {t.transmittance.srv.Get(), t.multipleScattering.srv.Get()}, {camera_.skyView.uav.Get()});
    context->Dispatch(groupCount(static_cast<unsigned>(sampling.skyViewWidth), kGroup), groupCount(static_cast<unsigned>(sampling.skyViewHeight), kGroup), 1);
    unbindCompute(context, 2, 1);

    bindCompute(context, shaders.computeShader(kAerialPerspective), {t.transmittance.srv.Get(), t.multipleScattering.srv.Get()},
                {camera_.aerialInscattering.uav.Get(), camera_.aerialTransmittance.uav.Get()});
    const unsigned columns = groupCount(static_cast<unsigned>(sampling.froxels), kGroup);
    context->Dispatch(columns, columns, 1);
    unbindCompute(context, 2, 2);
}

void HillairePass::render(ID3D11DeviceContext* context, ShaderLibrary& shaders, AtmospherePart part, const HillairePrecomputation& tables,
                          ID3D11Buffer* frameConstants, ID3D11ShaderResourceView* sceneRadiance, ID3D11ShaderResourceView* depth,
                          const Texture2D& target, Columns columns) {
    // The constants makeCameraTables() set stay in the buffers.
    gpu::HillairePassConstants constants{};
    constants.sun = sunDiscConstants();
    pass_.update(context, constants);
    fullscreen_.bindTarget(context, target.rtv.Get(), target.width, target.height, columns);
    const HillaireTables& t = tables.tables();
    fullscreen_.draw(context, shaders, atmosphereVertexShader(kShaderFile), atmospherePixelShader(kShaderFile, part),
                     {frameConstants, atmosphere_.get(), hillaire_.get(), pass_.get()},
                     {sceneRadiance, depth, t.transmittance.srv.Get(), t.multipleScattering.srv.Get(), camera_.skyView.srv.Get(),
                      camera_.aerialInscattering.srv.Get(), camera_.aerialTransmittance.srv.Get()},
                     linearClamp_.Get());
}

}  // namespace firmament
