#include "atmosphere/bruneton/BrunetonPrecomputation.h"

#include "atmosphere/TableFileSupport.h"
#include "core/Log.h"

#include <algorithm>
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

unsigned groups(unsigned count, unsigned size) { return (count + size - 1) / size; }
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
    : device_(device), parameters_(parameters), atmosphere_(device), bruneton_(device), slab_(device),
      linearClamp_(createLinearClampSampler(device)) {
    const auto& n = parameters_.lut;
    const glm::ivec3 packed = n.packed3d();
    tables_.transmittance = createColorTexture(device, n.transmittanceMu, n.transmittanceR, DXGI_FORMAT_R32G32B32A32_FLOAT, kReadWrite);
    tables_.irradiance = createColorTexture(device, n.irradianceMuS, n.irradianceR, DXGI_FORMAT_R32G32B32A32_FLOAT, kReadWrite);
    tables_.inscatter = createTexture3D(device, packed.x, packed.y, packed.z, DXGI_FORMAT_R16G16B16A16_FLOAT, kReadWrite);
    sphereDirectionsView_ = createSphereDirectionsView(device, parameters_.physics.sphereSamples);

    const auto slabs = [&](Stage stage, unsigned perUnit, int order) {
        const unsigned layers = static_cast<unsigned>(n.r);
        for (unsigned first = 0; first < layers; first += perUnit) units_.push_back({stage, first, std::min(first + perUnit, layers), order});
    };
    const int orders = parameters_.physics.scatteringOrders;
    units_.push_back({Stage::Transmittance, 0, 1, 0});
    units_.push_back({Stage::DirectIrradiance, 0, 1, 0});
    slabs(Stage::SingleScattering, kIntegralLayersPerUnit, 1);
    slabs(Stage::Initial, static_cast<unsigned>(n.r), 1);
    for (int order = 2; order <= orders; ++order) {
        slabs(Stage::ScatteredRadiance, kScatteredRadianceLayersPerUnit, order);
        units_.push_back({Stage::IndirectIrradiance, 0, 1, order});
        slabs(Stage::ScatteringOrder, kIntegralLayersPerUnit, order);
        units_.push_back({Stage::AccumulateIrradiance, 0, 1, order});
        slabs(Stage::AccumulateInscatter, static_cast<unsigned>(n.r), order);
    }
}

// The sums end in the textures the last order writes, which are the tables themselves.
// Order n writes the sums [n % 2]; with one order only, S is [1] (written by Initial) and E [0]
// (cleared).
void BrunetonPrecomputation::allocateScratch() {
    const auto& n = parameters_.lut;
    const glm::ivec3 packed = n.packed3d();
    const int last = parameters_.physics.scatteringOrders;
    const int result = last >= 2 ? last % 2 : 1;
    inscatterSums_[result] = tables_.inscatter;
    inscatterSums_[1 - result] = createTexture3D(device_, packed.x, packed.y, packed.z, DXGI_FORMAT_R16G16B16A16_FLOAT, kReadWrite);
    const int irradianceResult = last >= 2 ? last % 2 : 0;
    irradianceSums_[irradianceResult] = tables_.irradiance;
    irradianceSums_[1 - irradianceResult] =
        createColorTexture(device_, n.irradianceMuS, n.irradianceR, DXGI_FORMAT_R32G32B32A32_FLOAT, kReadWrite);
    deltaIrradiance_ = createColorTexture(device_, n.irradianceMuS, n.irradianceR, DXGI_FORMAT_R32G32B32A32_FLOAT, kReadWrite);
    deltaRayleigh_ = createTexture3D(device_, packed.x, packed.y, packed.z, DXGI_FORMAT_R32G32B32A32_FLOAT, kReadWrite);
    deltaMie_ = createTexture3D(device_, packed.x, packed.y, packed.z, DXGI_FORMAT_R32G32B32A32_FLOAT, kReadWrite);
    if (last >= 2) deltaJ_ = createTexture3D(device_, packed.x, packed.y, packed.z, DXGI_FORMAT_R32G32B32A32_FLOAT, kReadWrite);
}

void BrunetonPrecomputation::releaseScratch() {
    deltaIrradiance_ = {};
    irradianceSums_[0] = irradianceSums_[1] = {};
    deltaRayleigh_ = deltaMie_ = deltaJ_ = {};
    inscatterSums_[0] = inscatterSums_[1] = {};
}

std::string BrunetonPrecomputation::currentStage() const {
    if (done()) return "done";
    const Unit& u = units_[next_];
    const std::string order = "order " + std::to_string(u.order) + ": ";
    switch (u.stage) {
        case Stage::Transmittance: return "transmittance";
        case Stage::DirectIrradiance: return "direct irradiance";
        case Stage::SingleScattering: return "single in-scattering";
        case Stage::Initial: return "in-scatter table";
        case Stage::ScatteredRadiance: return order + "scattered radiance J";
        case Stage::IndirectIrradiance: return order + "ground irradiance";
        case Stage::ScatteringOrder: return order + "in-scattering";
        case Stage::AccumulateIrradiance: return order + "irradiance sum";
        case Stage::AccumulateInscatter: return order + "in-scatter sum";
    }
    return {};
}

void BrunetonPrecomputation::run(ID3D11DeviceContext* context, ShaderLibrary& shaders, const Unit& unit) {
    atmosphere_.update(context, parameters_.physics.constants());
    bruneton_.update(context, parameters_.constants(unit.order));
    gpu::PrecomputeSliceConstants slab{};
    slab.range = glm::uvec4(unit.first, unit.end, 0u, 0u);
    slab_.update(context, slab);
    ID3D11Buffer* buffers[3] = {atmosphere_.get(), bruneton_.get(), slab_.get()};
    context->CSSetConstantBuffers(0, 3, buffers);
    context->CSSetSamplers(0, 1, linearClamp_.GetAddressOf());
    const auto& n = parameters_.lut;
    const glm::ivec3 packed = n.packed3d();
    const auto bind = [&](const ShaderKey& key, std::initializer_list<ID3D11ShaderResourceView*> inputs,
                          std::initializer_list<ID3D11UnorderedAccessView*> outputs) {
        context->CSSetShader(shaders.computeShader(key), nullptr, 0);
        context->CSSetShaderResources(0, static_cast<UINT>(inputs.size()), inputs.begin());
        context->CSSetUnorderedAccessViews(0, static_cast<UINT>(outputs.size()), outputs.begin(), nullptr);
    };
    const auto dispatchLayers = [&] {
        context->Dispatch(groups(static_cast<unsigned>(packed.x), kGroup), groups(static_cast<unsigned>(packed.y), kGroup), unit.end - unit.first);
    };
    const auto dispatchIrradiance = [&] {
        context->Dispatch(groups(static_cast<unsigned>(n.irradianceMuS), kGroup), groups(static_cast<unsigned>(n.irradianceR), kGroup), 1);
    };
    ID3D11ShaderResourceView* transmittance = tables_.transmittance.srv.Get();
    const int o = unit.order;
    switch (unit.stage) {
        case Stage::Transmittance:
            bind(kTransmittance, {}, {tables_.transmittance.uav.Get()});
            context->Dispatch(groups(static_cast<unsigned>(n.transmittanceMu), kGroup), groups(static_cast<unsigned>(n.transmittanceR), kGroup), 1);
            break;
        case Stage::DirectIrradiance: {
            bind(kDirectIrradiance, {transmittance}, {deltaIrradiance_.uav.Get()});
            dispatchIrradiance();
            const float zero[4] = {};  // E holds the sky's light only: none before order 2
            context->ClearUnorderedAccessViewFloat(irradianceSums_[1].uav.Get(), zero);
            context->ClearUnorderedAccessViewFloat(irradianceSums_[0].uav.Get(), zero);
            break;
        }
        case Stage::SingleScattering:
            bind(kSingleScattering, {transmittance}, {deltaRayleigh_.uav.Get(), deltaMie_.uav.Get()});
            dispatchLayers();
            break;
        case Stage::Initial:
            bind(kInitial, {transmittance, deltaRayleigh_.srv.Get(), deltaMie_.srv.Get()}, {inscatterSums_[1].uav.Get()});
            dispatchLayers();
            break;
        case Stage::ScatteredRadiance:
            bind(kScatteredRadiance, {transmittance, deltaRayleigh_.srv.Get(), deltaMie_.srv.Get(), deltaIrradiance_.srv.Get(), sphereDirectionsView_.Get()},
                 {deltaJ_.uav.Get()});
            dispatchLayers();
            break;
        case Stage::IndirectIrradiance:
            bind(kIndirectIrradiance, {transmittance, deltaRayleigh_.srv.Get(), deltaMie_.srv.Get(), sphereDirectionsView_.Get()},
                 {deltaIrradiance_.uav.Get()});
            dispatchIrradiance();
            break;
        case Stage::ScatteringOrder:  // delta S of order n replaces order n - 1's in deltaRayleigh_
            bind(kScatteringOrder, {transmittance, deltaJ_.srv.Get()}, {deltaRayleigh_.uav.Get()});
            dispatchLayers();
            break;
        case Stage::AccumulateIrradiance:
            bind(kAccumulateIrradiance, {irradianceSums_[(o + 1) % 2].srv.Get(), deltaIrradiance_.srv.Get()}, {irradianceSums_[o % 2].uav.Get()});
            dispatchIrradiance();
            break;
        case Stage::AccumulateInscatter:
            bind(kAccumulateInscatter, {transmittance, inscatterSums_[(o + 1) % 2].srv.Get(), deltaRayleigh_.srv.Get()},
                 {inscatterSums_[o % 2].uav.Get()});
            dispatchLayers();
            break;
    }
    ID3D11UnorderedAccessView* noUavs[2] = {};
    ID3D11ShaderResourceView* noSrvs[5] = {};
    context->CSSetUnorderedAccessViews(0, 2, noUavs, nullptr);
    context->CSSetShaderResources(0, 5, noSrvs);
}

bool BrunetonPrecomputation::step(ID3D11DeviceContext* context, ShaderLibrary& shaders) {
    if (done()) return false;
    if (next_ == 0) allocateScratch();
    run(context, shaders, units_[next_++]);
    if (done()) releaseScratch();
    return true;
}

void BrunetonPrecomputation::runAll(ID3D11DeviceContext* context, ShaderLibrary& shaders) {
    const auto& n = parameters_.lut;
    char what[200];
    std::snprintf(what, sizeof(what), "transmittance %dx%d, irradiance %dx%d, in-scatter %dx%dx%dx%d with orders up to %d", n.transmittanceMu,
                  n.transmittanceR, n.irradianceMuS, n.irradianceR, n.r, n.mu, n.muS, n.nu, parameters_.physics.scatteringOrders);
    log::info(std::string("atmosphere (Bruneton 2008): pre-computing ") + what);
    runAllUnits(context, "atmosphere (Bruneton 2008): ",
                {[&] { return step(context, shaders); }, [&] { return progress(); }, [&] { return currentStage(); }});
}

}  // namespace firmament
