#include "atmosphere/bruneton/BrunetonPrecomputation.h"

#include "tables/TableFiles.h"

#include <cstdio>

namespace firmament {

namespace {
const ShaderKey kTransmittance{"atmosphere/bruneton/precompute_transmittance.hlsl", "main", "cs_5_0", {}};
const ShaderKey kDirectIrradiance{"atmosphere/bruneton/precompute_irradiance.hlsl", "direct", "cs_5_0", {}};
const ShaderKey kIndirectIrradiance{"atmosphere/bruneton/precompute_irradiance.hlsl", "indirect", "cs_5_0", {}};
const ShaderKey kAccumulateIrradiance{"atmosphere/bruneton/precompute_irradiance.hlsl", "accumulate", "cs_5_0", {}};
const ShaderKey kSingleScattering{"atmosphere/bruneton/precompute_inscatter.hlsl", "singleScattering", "cs_5_0", {}};
const ShaderKey kInitial{"atmosphere/bruneton/precompute_inscatter.hlsl", "initial", "cs_5_0", {}};
const ShaderKey kScatteredRadiance{"atmosphere/bruneton/precompute_inscatter.hlsl", "scatteredRadiance", "cs_5_0", {}};
const ShaderKey kScatteringOrder{"atmosphere/bruneton/precompute_inscatter.hlsl", "order", "cs_5_0", {}};
const ShaderKey kAccumulateInscatter{"atmosphere/bruneton/precompute_inscatter.hlsl", "accumulate", "cs_5_0", {}};

constexpr unsigned kGroup = 8;  // every shader: 8 x 8 x 1
// Radius layers per unit: about 0.1-0.5 s each on the WARP device at the full size.
constexpr unsigned kIntegralLayersPerUnit = 8;
constexpr unsigned kScatteredRadianceLayersPerUnit = 2;  // 128 directions per texel

constexpr UINT kReadWrite = D3D11_BIND_SHADER_RESOURCE | D3D11_BIND_UNORDERED_ACCESS;

void runUnit(ID3D11DeviceContext* context, ShaderLibrary& shaders, const WorkUnit<BrunetonStage>& unit, const BrunetonParameters& parameters,
             const BrunetonTables& tables, BrunetonScratch& scratch);
}  // namespace

BrunetonParameters BrunetonParameters::from(const AtmosphereSettings& settings) {
    BrunetonParameters p;
    p.physics = AtmosphereParameters::from(settings);
    p.lut = atmosphere::bruneton::Dimensions::of(settings.resolution);
    p.groundAlbedo = settings.groundAlbedo;
    return p;
}

gpu::BrunetonConstants BrunetonParameters::constants(int order) const {
    gpu::BrunetonConstants c{};
    c.transmittanceSize = glm::vec4(lut.transmittanceMu, lut.transmittanceR, 0.0f, 0.0f);
    c.irradianceSize = glm::vec4(lut.irradianceMuS, lut.irradianceR, 0.0f, 0.0f);
    c.inscatterSize = glm::vec4(lut.r, lut.mu, lut.muS, lut.nu);
    c.ground = glm::vec4(static_cast<float>(groundAlbedo), static_cast<float>(order), 0.0f, 0.0f);
    return c;
}

std::string BrunetonParameters::describe() const {
    char text[200];
    std::snprintf(text, sizeof(text), " model=Bruneton2008 transmittance=%dx%d irradiance=%dx%d inscatter=%dx%dx%dx%d groundAlbedo=%.17g",
                  lut.transmittanceMu, lut.transmittanceR, lut.irradianceMuS, lut.irradianceR, lut.r, lut.mu, lut.muS, lut.nu, groundAlbedo);
    return physics.describe() + text;
}

std::string brunetonTableKey(const BrunetonParameters& parameters, ShaderLibrary& shaders) {
    const ShaderKey precompute[] = {kTransmittance, kDirectIrradiance, kIndirectIrradiance, kAccumulateIrradiance, kSingleScattering,
                                    kInitial,       kScatteredRadiance, kScatteringOrder,  kAccumulateInscatter};
    return tableKey(parameters.describe(), shaders, precompute);
}

BrunetonPrecomputation::BrunetonPrecomputation(ID3D11Device* device, const BrunetonParameters& parameters)
    : StagedComputation("atmosphere (Bruneton 2008): ", device, parameters, runUnit) {
    const auto& n = parameters_.lut;
    const glm::ivec3 packed = n.packed3d();
    tables_.transmittance = createColorTexture(device, n.transmittanceMu, n.transmittanceR, DXGI_FORMAT_R32G32B32A32_FLOAT, kReadWrite);
    tables_.irradiance = createColorTexture(device, n.irradianceMuS, n.irradianceR, DXGI_FORMAT_R32G32B32A32_FLOAT, kReadWrite);
    tables_.inscatter = createTexture3D(device, packed.x, packed.y, packed.z, DXGI_FORMAT_R16G16B16A16_FLOAT, kReadWrite);

    const unsigned layers = static_cast<unsigned>(n.r);
    const int orders = parameters_.physics.scatteringOrders;
    addUnit(BrunetonStage::Transmittance);
    addUnit(BrunetonStage::DirectIrradiance);
    addSlabs(BrunetonStage::SingleScattering, layers, kIntegralLayersPerUnit, 1);
    addSlabs(BrunetonStage::Initial, layers, layers, 1);
    for (int order = 2; order <= orders; ++order) {
        addSlabs(BrunetonStage::ScatteredRadiance, layers, kScatteredRadianceLayersPerUnit, order);
        addUnit(BrunetonStage::IndirectIrradiance, order);
        addSlabs(BrunetonStage::ScatteringOrder, layers, kIntegralLayersPerUnit, order);
        addUnit(BrunetonStage::AccumulateIrradiance, order);
        addSlabs(BrunetonStage::AccumulateInscatter, layers, layers, order);
    }
}

// The sums end in the textures the last order writes, which are the tables themselves.
// Order n writes the sums [n % 2]; with one order only, S is [1] (written by Initial) and E [0]
// (cleared).
BrunetonScratch::BrunetonScratch(ID3D11Device* device, const BrunetonParameters& parameters, const BrunetonTables& tables)
    : inputs(device, parameters.physics.sphereSamples), bruneton(device) {
    const auto& n = parameters.lut;
    const glm::ivec3 packed = n.packed3d();
    const int last = parameters.physics.scatteringOrders;
    const int result = last >= 2 ? last % 2 : 1;
    inscatterSums[result] = tables.inscatter;
    inscatterSums[1 - result] = createTexture3D(device, packed.x, packed.y, packed.z, DXGI_FORMAT_R16G16B16A16_FLOAT, kReadWrite);
    const int irradianceResult = last >= 2 ? last % 2 : 0;
    irradianceSums[irradianceResult] = tables.irradiance;
    irradianceSums[1 - irradianceResult] = createColorTexture(device, n.irradianceMuS, n.irradianceR, DXGI_FORMAT_R32G32B32A32_FLOAT, kReadWrite);
    deltaIrradiance = createColorTexture(device, n.irradianceMuS, n.irradianceR, DXGI_FORMAT_R32G32B32A32_FLOAT, kReadWrite);
    deltaRayleigh = createTexture3D(device, packed.x, packed.y, packed.z, DXGI_FORMAT_R32G32B32A32_FLOAT, kReadWrite);
    deltaMie = createTexture3D(device, packed.x, packed.y, packed.z, DXGI_FORMAT_R32G32B32A32_FLOAT, kReadWrite);
    if (last >= 2) deltaJ = createTexture3D(device, packed.x, packed.y, packed.z, DXGI_FORMAT_R32G32B32A32_FLOAT, kReadWrite);
}

std::string stageName(BrunetonStage stage, int order) {
    const std::string prefix = "order " + std::to_string(order) + ": ";
    switch (stage) {
        case BrunetonStage::Transmittance: return "transmittance";
        case BrunetonStage::DirectIrradiance: return "direct irradiance";
        case BrunetonStage::SingleScattering: return "single in-scattering";
        case BrunetonStage::Initial: return "in-scatter table";
        case BrunetonStage::ScatteredRadiance: return prefix + "scattered radiance J";
        case BrunetonStage::IndirectIrradiance: return prefix + "ground irradiance";
        case BrunetonStage::ScatteringOrder: return prefix + "in-scattering";
        case BrunetonStage::AccumulateIrradiance: return prefix + "irradiance sum";
        case BrunetonStage::AccumulateInscatter: return prefix + "in-scatter sum";
    }
    return {};
}

std::string describeTables(const BrunetonParameters& parameters) {
    const auto& n = parameters.lut;
    char what[200];
    std::snprintf(what, sizeof(what), "transmittance %dx%d, irradiance %dx%d, in-scatter %dx%dx%dx%d with orders up to %d", n.transmittanceMu,
                  n.transmittanceR, n.irradianceMuS, n.irradianceR, n.r, n.mu, n.muS, n.nu, parameters.physics.scatteringOrders);
    return what;
}

namespace {

// Binds and dispatches one unit's shader.
void runUnit(ID3D11DeviceContext* context, ShaderLibrary& shaders, const WorkUnit<BrunetonStage>& unit, const BrunetonParameters& parameters,
             const BrunetonTables& tables, BrunetonScratch& scratch) {
    scratch.bruneton.update(context, parameters.constants(unit.order));
    scratch.inputs.bind(context, parameters.physics.constants(), scratch.bruneton.get(), unit.first, unit.end);
    const auto& n = parameters.lut;
    const glm::ivec3 packed = n.packed3d();
    const auto bind = [&](const ShaderKey& key, std::initializer_list<ID3D11ShaderResourceView*> inputs,
                          std::initializer_list<ID3D11UnorderedAccessView*> outputs) { bindCompute(context, shaders.computeShader(key), inputs, outputs); };
    const auto dispatchLayers = [&] {
        context->Dispatch(groupCount(static_cast<unsigned>(packed.x), kGroup), groupCount(static_cast<unsigned>(packed.y), kGroup), unit.end - unit.first);
    };
    const auto dispatchIrradiance = [&] {
        context->Dispatch(groupCount(static_cast<unsigned>(n.irradianceMuS), kGroup), groupCount(static_cast<unsigned>(n.irradianceR), kGroup), 1);
    };
    ID3D11ShaderResourceView* transmittance = tables.transmittance.srv.Get();
    const int o = unit.order;
    switch (unit.stage) {
        case BrunetonStage::Transmittance:
            bind(kTransmittance, {}, {tables.transmittance.uav.Get()});
            context->Dispatch(groupCount(static_cast<unsigned>(n.transmittanceMu), kGroup), groupCount(static_cast<unsigned>(n.transmittanceR), kGroup), 1);
            break;
        case BrunetonStage::DirectIrradiance: {
            bind(kDirectIrradiance, {transmittance}, {scratch.deltaIrradiance.uav.Get()});
            dispatchIrradiance();
            const float zero[4] = {};  // E holds the sky's light only: none before order 2
            context->ClearUnorderedAccessViewFloat(scratch.irradianceSums[1].uav.Get(), zero);
            context->ClearUnorderedAccessViewFloat(scratch.irradianceSums[0].uav.Get(), zero);
            break;
        }
        case BrunetonStage::SingleScattering:
            bind(kSingleScattering, {transmittance}, {scratch.deltaRayleigh.uav.Get(), scratch.deltaMie.uav.Get()});
            dispatchLayers();
            break;
        case BrunetonStage::Initial:
            bind(kInitial, {transmittance, scratch.deltaRayleigh.srv.Get(), scratch.deltaMie.srv.Get()}, {scratch.inscatterSums[1].uav.Get()});
            dispatchLayers();
            break;
        case BrunetonStage::ScatteredRadiance:
            bind(kScatteredRadiance, {transmittance, scratch.deltaRayleigh.srv.Get(), scratch.deltaMie.srv.Get(), scratch.deltaIrradiance.srv.Get(), scratch.inputs.sphereDirections()},
                 {scratch.deltaJ.uav.Get()});
            dispatchLayers();
            break;
        case BrunetonStage::IndirectIrradiance:
            bind(kIndirectIrradiance, {transmittance, scratch.deltaRayleigh.srv.Get(), scratch.deltaMie.srv.Get(), scratch.inputs.sphereDirections()},
                 {scratch.deltaIrradiance.uav.Get()});
            dispatchIrradiance();
            break;
        case BrunetonStage::ScatteringOrder:  // delta S of order n replaces order n - 1's in the delta Rayleigh texture
            bind(kScatteringOrder, {transmittance, scratch.deltaJ.srv.Get()}, {scratch.deltaRayleigh.uav.Get()});
            dispatchLayers();
            break;
        case BrunetonStage::AccumulateIrradiance:
            bind(kAccumulateIrradiance, {scratch.irradianceSums[(o + 1) % 2].srv.Get(), scratch.deltaIrradiance.srv.Get()}, {scratch.irradianceSums[o % 2].uav.Get()});
            dispatchIrradiance();
            break;
        case BrunetonStage::AccumulateInscatter:
            bind(kAccumulateInscatter, {transmittance, scratch.inscatterSums[(o + 1) % 2].srv.Get(), scratch.deltaRayleigh.srv.Get()},
                 {scratch.inscatterSums[o % 2].uav.Get()});
            dispatchLayers();
            break;
    }
    unbindCompute(context, 5, 2);
}

}  // namespace

}  // namespace firmament
