#include "atmosphere/yusov/YusovPrecomputation.h"

#include <cstdio>

namespace firmament {

namespace {
const ShaderKey kNetDensity{"atmosphere/yusov/precompute_net_density.hlsl", "main", "cs_5_0", {}};
const ShaderKey kSingleScattering{"atmosphere/yusov/precompute_single_scattering.hlsl", "main", "cs_5_0", {}};
const ShaderKey kScatteredRadianceFromSingle{"atmosphere/yusov/precompute_multiple_scattering.hlsl", "scatteredRadianceFromSingle", "cs_5_0", {}};
const ShaderKey kScatteredRadiance{"atmosphere/yusov/precompute_multiple_scattering.hlsl", "scatteredRadiance", "cs_5_0", {}};
const ShaderKey kScatteringOrder{"atmosphere/yusov/precompute_multiple_scattering.hlsl", "scatteringOrder", "cs_5_0", {}};
const ShaderKey kCombine{"atmosphere/yusov/precompute_multiple_scattering.hlsl", "combine", "cs_5_0", {}};
const ShaderKey kAmbientLight{"atmosphere/yusov/precompute_ambient_light.hlsl", "main", "cs_5_0", {}};

// Thread-group sizes of the shaders.
constexpr unsigned kNetDensityGroup[2] = {8, 8};
constexpr unsigned kScatteringGroup[3] = {4, 8, 4};
constexpr unsigned kAmbientGroup = 64;
// Work per unit: about 0.1-0.5 s each on the WARP device at the full resolution.
constexpr unsigned kNetDensityRowsPerUnit = 128;
constexpr unsigned kScatteringSlicesPerUnit = 64;
constexpr unsigned kScatteredRadianceSlicesPerUnit = 16;  // 128 look-ups per texel

constexpr DXGI_FORMAT kTableFormat = DXGI_FORMAT_R16G16B16A16_FLOAT;
constexpr UINT kReadWrite = D3D11_BIND_SHADER_RESOURCE | D3D11_BIND_UNORDERED_ACCESS;

void runUnit(ID3D11DeviceContext* context, ShaderLibrary& shaders, const WorkUnit<YusovStage>& unit, const AtmosphereParameters& parameters,
             const YusovTables& tables, YusovScratch& scratch);
}  // namespace

YusovPrecomputation::YusovPrecomputation(ID3D11Device* device, const AtmosphereParameters& parameters)
    : StagedComputation("atmosphere: ", device, parameters, runUnit) {
    const LutDimensions& n = parameters_.lut;
    const glm::ivec3 packed = n.packed3d();
    tables_.netDensity = createColorTexture(device, n.netDensityZenith, n.netDensityHeight, DXGI_FORMAT_R32G32B32A32_FLOAT, kReadWrite);
    // The tables of species: a bank of altitude texels for Rayleigh, one for Mie, side by side.
    tables_.singleScattering = createTexture3D(device, 2 * packed.x, packed.y, packed.z, kTableFormat, kReadWrite);
    tables_.multipleScattering = createTexture3D(device, 2 * packed.x, packed.y, packed.z, kTableFormat, kReadWrite);
    tables_.ambientLight = createColorTexture(device, n.ambientLight, 1, kTableFormat, kReadWrite);
    tables_.highOrderScattering = createTexture3D(device, packed.x, packed.y, packed.z, kTableFormat, kReadWrite);

    const unsigned depth = static_cast<unsigned>(packed.z);
    addSlabs(YusovStage::NetDensity, static_cast<unsigned>(n.netDensityHeight), kNetDensityRowsPerUnit);
    addSlabs(YusovStage::SingleScattering, depth, kScatteringSlicesPerUnit, 1);
    for (int order = 2; order <= parameters_.scatteringOrders; ++order) {
        addSlabs(YusovStage::ScatteredRadiance, depth, kScatteredRadianceSlicesPerUnit, order);
        addSlabs(YusovStage::ScatteringOrder, depth, kScatteringSlicesPerUnit, order);
    }
    addSlabs(YusovStage::Combine, depth, depth, parameters_.scatteringOrders);
    addUnit(YusovStage::AmbientLight);
}

// The high-order sum ends in the texture the last order writes, which is the table itself
// (order 1 only: the cleared one).
YusovScratch::YusovScratch(ID3D11Device* device, const AtmosphereParameters& parameters, const YusovTables& tables)
    : inputs(device, parameters.sphereSamples) {
    const glm::ivec3 packed = parameters.lut.packed3d();
    const int last = parameters.scatteringOrders;
    const int result = last >= 2 ? (last + 1) % 2 : 0;
    highOrders[result] = tables.highOrderScattering;
    if (last < 2) return;
    highOrders[1 - result] = createTexture3D(device, packed.x, packed.y, packed.z, kTableFormat, kReadWrite);
    // J is radiance per metre, about 1e-7 in these units: below half float's normal range
    // (6e-5), where it would keep one or two bits. Float32 holds it.
    scattered = createTexture3D(device, packed.x, packed.y, packed.z, DXGI_FORMAT_R32G32B32A32_FLOAT, kReadWrite);
    for (auto& texture : orders) texture = createTexture3D(device, packed.x, packed.y, packed.z, kTableFormat, kReadWrite);
}

std::string stageName(YusovStage stage, int order) {
    switch (stage) {
        case YusovStage::NetDensity: return "net density";
        case YusovStage::SingleScattering: return "single scattering";
        case YusovStage::ScatteredRadiance: return "order " + std::to_string(order) + ": scattered radiance J";
        case YusovStage::ScatteringOrder: return "order " + std::to_string(order) + ": in-scattering";
        case YusovStage::Combine: return "multiple scattering";
        case YusovStage::AmbientLight: return "ambient sky light";
    }
    return {};
}

std::span<const ShaderKey> yusovPrecomputeShaders() {
    static const ShaderKey all[] = {kNetDensity,      kSingleScattering, kScatteredRadianceFromSingle, kScatteredRadiance,
                                    kScatteringOrder, kCombine,          kAmbientLight};
    return all;
}

std::string describeTables(const AtmosphereParameters& parameters) {
    const LutDimensions& n = parameters.lut;
    char what[200];
    std::snprintf(what, sizeof(what), "net density %dx%d, scattering %dx%dx%dx%d with orders up to %d, ambient light %d",
                  n.netDensityZenith, n.netDensityHeight, n.height, n.viewZenith, n.sunZenith, n.sunView, parameters.scatteringOrders,
                  n.ambientLight);
    return what;
}

namespace {

// Binds and dispatches one unit's shader.
void runUnit(ID3D11DeviceContext* context, ShaderLibrary& shaders, const WorkUnit<YusovStage>& unit, const AtmosphereParameters& parameters,
             const YusovTables& tables, YusovScratch& scratch) {
    scratch.inputs.bind(context, parameters.constants(), nullptr, unit.first, unit.end);
    const LutDimensions& n = parameters.lut;
    const auto bind = [&](const ShaderKey& key, std::initializer_list<ID3D11ShaderResourceView*> inputs,
                          std::initializer_list<ID3D11UnorderedAccessView*> outputs) { bindCompute(context, shaders.computeShader(key), inputs, outputs); };
    const auto dispatchTable = [&] {
        context->Dispatch(groupCount(static_cast<unsigned>(n.height), kScatteringGroup[0]),
                          groupCount(static_cast<unsigned>(n.viewZenith), kScatteringGroup[1]), groupCount(unit.end - unit.first, kScatteringGroup[2]));
    };
    // Order n reads order n - 1 (the single scattering table for n = 2) and writes orders[n % 2];
    // the high-order sum goes from highOrders[n % 2] to highOrders[(n + 1) % 2].
    const int o = unit.order;
    switch (unit.stage) {
        case YusovStage::NetDensity:
            bind(kNetDensity, {}, {tables.netDensity.uav.Get()});
            context->Dispatch(groupCount(static_cast<unsigned>(n.netDensityZenith), kNetDensityGroup[0]),
                              groupCount(unit.end - unit.first, kNetDensityGroup[1]), 1);
            break;
        case YusovStage::SingleScattering:
            bind(kSingleScattering, {tables.netDensity.srv.Get()}, {tables.singleScattering.uav.Get()});
            if (unit.first == 0) {  // before order 2 the high-order sum is zero
                const float zero[4] = {};
                context->ClearUnorderedAccessViewFloat(scratch.highOrders[0].uav.Get(), zero);
            }
            dispatchTable();
            break;
        case YusovStage::ScatteredRadiance: {
            ID3D11ShaderResourceView* previous = o == 2 ? tables.singleScattering.srv.Get() : scratch.orders[(o - 1) % 2].srv.Get();
            bind(o == 2 ? kScatteredRadianceFromSingle : kScatteredRadiance, {previous, scratch.inputs.sphereDirections()},
                 {scratch.scattered.uav.Get()});
            dispatchTable();
            break;
        }
        case YusovStage::ScatteringOrder:
            bind(kScatteringOrder, {scratch.scattered.srv.Get(), nullptr, scratch.highOrders[o % 2].srv.Get()},
                 {scratch.orders[o % 2].uav.Get(), scratch.highOrders[(o + 1) % 2].uav.Get()});
            dispatchTable();
            break;
        case YusovStage::Combine: {
            const Texture3D& high = o >= 2 ? scratch.highOrders[(o + 1) % 2] : scratch.highOrders[0];
            bind(kCombine, {tables.singleScattering.srv.Get(), nullptr, high.srv.Get()}, {tables.multipleScattering.uav.Get()});
            dispatchTable();
            break;
        }
        case YusovStage::AmbientLight:
            bind(kAmbientLight, {tables.multipleScattering.srv.Get(), scratch.inputs.sphereDirections()}, {tables.ambientLight.uav.Get()});
            context->Dispatch(groupCount(static_cast<unsigned>(n.ambientLight), kAmbientGroup), 1, 1);
            break;
    }
    unbindCompute(context, 3, 2);
}

}  // namespace

}  // namespace firmament
