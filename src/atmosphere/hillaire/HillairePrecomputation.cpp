#include "atmosphere/hillaire/HillairePrecomputation.h"

#include "tables/SphereDirections.h"
#include "tables/TableFiles.h"

#include <cstdio>

namespace firmament {

namespace {
const ShaderKey kTransmittance{"atmosphere/hillaire/precompute_transmittance.hlsl", "main", "cs_5_0", {}};
const ShaderKey kMultipleScattering{"atmosphere/hillaire/precompute_multiple_scattering.hlsl", "main", "cs_5_0", {}};
const ShaderKey kIrradiance{"atmosphere/hillaire/precompute_irradiance.hlsl", "main", "cs_5_0", {}};

constexpr unsigned kGroup = 8;  // both shaders: 8 x 8 x 1
constexpr UINT kReadWrite = D3D11_BIND_SHADER_RESOURCE | D3D11_BIND_UNORDERED_ACCESS;

void runUnit(ID3D11DeviceContext* context, ShaderLibrary& shaders, const WorkUnit<HillaireStage>& unit, const HillaireParameters& parameters,
             const HillaireTables& tables, HillaireScratch& scratch) {
    scratch.hillaire.update(context, parameters.constants());
    scratch.inputs.bind(context, parameters.physics.constants(), scratch.hillaire.get(), unit.first, unit.end);
    const auto& n = parameters.lut;
    switch (unit.stage) {
        case HillaireStage::Transmittance:
            bindCompute(context, shaders.computeShader(kTransmittance), {}, {tables.transmittance.uav.Get()});
            context->Dispatch(groupCount(static_cast<unsigned>(n.transmittanceMu), kGroup), groupCount(static_cast<unsigned>(n.transmittanceR), kGroup), 1);
            unbindCompute(context, 0, 1);
            break;
        case HillaireStage::MultipleScattering:
            bindCompute(context, shaders.computeShader(kMultipleScattering), {tables.transmittance.srv.Get(), scratch.inputs.sphereDirections()},
                        {tables.multipleScattering.uav.Get()});
            context->Dispatch(groupCount(static_cast<unsigned>(n.multipleScatteringMuS), kGroup),
                              groupCount(static_cast<unsigned>(n.multipleScatteringR), kGroup), 1);
            unbindCompute(context, 2, 1);
            break;
        case HillaireStage::Irradiance:
            bindCompute(context, shaders.computeShader(kIrradiance),
                        {tables.transmittance.srv.Get(), tables.multipleScattering.srv.Get(), scratch.irradianceDirections.Get()},
                        {tables.irradiance.uav.Get()});
            context->Dispatch(groupCount(static_cast<unsigned>(n.irradianceMuS), kGroup), groupCount(static_cast<unsigned>(n.irradianceR), kGroup), 1);
            unbindCompute(context, 3, 1);
            break;
    }
}
}  // namespace

gpu::HillaireConstants HillaireParameters::constants() const {
    gpu::HillaireConstants c{};
    c.transmittanceSize = glm::vec4(static_cast<float>(lut.transmittanceMu), static_cast<float>(lut.transmittanceR), 0.0f, 0.0f);
    c.multipleScatteringSize = glm::vec4(static_cast<float>(lut.multipleScatteringMuS), static_cast<float>(lut.multipleScatteringR),
                                         static_cast<float>(multipleScatteringDirections), static_cast<float>(multipleScatteringSteps));
    c.irradianceSize = glm::vec4(static_cast<float>(lut.irradianceMuS), static_cast<float>(lut.irradianceR), static_cast<float>(irradianceDirections),
                                 static_cast<float>(irradianceSteps));
    return c;
}

HillaireParameters HillaireParameters::from(const AtmosphereSettings& settings) {
    HillaireParameters p;
    p.physics = AtmosphereParameters::from(settings);
    p.lut = atmosphere::hillaire::Dimensions::of(settings.resolution);
    p.multipleScatteringDirections = settings.hillaireMultipleScatteringDirections;
    p.multipleScatteringSteps = settings.hillaireMultipleScatteringSteps;
    p.lut.multipleScatteringMuS *= settings.hillaireMultipleScatteringDetail;
    p.lut.multipleScatteringR *= settings.hillaireMultipleScatteringDetail;
    return p;
}

std::string hillaireTableKey(const HillaireParameters& parameters, ShaderLibrary& shaders) {
    const ShaderKey precompute[] = {kTransmittance, kMultipleScattering, kIrradiance};
    return tableKey(parameters.describe(), shaders, precompute);
}

std::string HillaireParameters::describe() const {
    char text[256];
    std::snprintf(text, sizeof(text), " model=Hillaire2020 transmittance=%dx%d multipleScattering=%dx%d directions=%d steps=%d irradiance=%dx%d directions=%d steps=%d",
                  lut.transmittanceMu, lut.transmittanceR, lut.multipleScatteringMuS, lut.multipleScatteringR, multipleScatteringDirections,
                  multipleScatteringSteps, lut.irradianceMuS, lut.irradianceR, irradianceDirections, irradianceSteps);
    return physics.describe() + text;
}

std::string stageName(HillaireStage stage, int) {
    switch (stage) {
        case HillaireStage::Transmittance: return "transmittance";
        case HillaireStage::MultipleScattering: return "multiple scattering";
        case HillaireStage::Irradiance: return "sky irradiance";
    }
    return "?";
}

std::string describeTables(const HillaireParameters& parameters) {
    const auto& n = parameters.lut;
    char what[256];
    std::snprintf(what, sizeof(what), "transmittance %dx%d, multiple scattering %dx%d (%d directions of %d steps), sky irradiance %dx%d (%d of %d)",
                  n.transmittanceMu, n.transmittanceR, n.multipleScatteringMuS, n.multipleScatteringR, parameters.multipleScatteringDirections,
                  parameters.multipleScatteringSteps, n.irradianceMuS, n.irradianceR, parameters.irradianceDirections, parameters.irradianceSteps);
    return what;
}

HillaireScratch::HillaireScratch(ID3D11Device* device, const HillaireParameters& parameters, const HillaireTables&)
    : inputs(device, parameters.multipleScatteringDirections),
      irradianceDirections(createSphereDirectionsView(device, parameters.irradianceDirections)),
      hillaire(device) {}

HillairePrecomputation::HillairePrecomputation(ID3D11Device* device, const HillaireParameters& parameters)
    : StagedComputation("atmosphere (Hillaire 2020): ", device, parameters, runUnit) {
    const auto& n = parameters_.lut;
    tables_.transmittance = createColorTexture(device, n.transmittanceMu, n.transmittanceR, DXGI_FORMAT_R32G32B32A32_FLOAT, kReadWrite);
    tables_.multipleScattering = createColorTexture(device, n.multipleScatteringMuS, n.multipleScatteringR, DXGI_FORMAT_R32G32B32A32_FLOAT, kReadWrite);
    addUnit(HillaireStage::Transmittance);
    tables_.irradiance = createColorTexture(device, n.irradianceMuS, n.irradianceR, DXGI_FORMAT_R32G32B32A32_FLOAT, kReadWrite);
    addUnit(HillaireStage::MultipleScattering);
    addUnit(HillaireStage::Irradiance);
}

}  // namespace firmament
