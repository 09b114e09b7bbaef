#include "atmosphere/ScatteringPrecomputation.h"

#include "core/Log.h"
#include "gpu/Hresult.h"

#include <algorithm>
#include <cmath>
#include <cstdio>

namespace firmament {

namespace {
const ShaderKey kNetDensity{"atmosphere/precompute_net_density.hlsl", "main", "cs_5_0", {}};
const ShaderKey kSingleScattering{"atmosphere/precompute_single_scattering.hlsl", "main", "cs_5_0", {}};
const ShaderKey kScatteredRadiance{"atmosphere/precompute_multiple_scattering.hlsl", "scatteredRadiance", "cs_5_0", {}};
const ShaderKey kScatteringOrder{"atmosphere/precompute_multiple_scattering.hlsl", "scatteringOrder", "cs_5_0", {}};
const ShaderKey kCombine{"atmosphere/precompute_multiple_scattering.hlsl", "combine", "cs_5_0", {}};
const ShaderKey kAmbientLight{"atmosphere/precompute_ambient_light.hlsl", "main", "cs_5_0", {}};

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

unsigned groups(unsigned count, unsigned size) { return (count + size - 1) / size; }
}  // namespace

ScatteringPrecomputation::ScatteringPrecomputation(ID3D11Device* device, const AtmosphereParameters& parameters)
    : device_(device), parameters_(parameters), atmosphere_(device), slab_(device), linearClamp_(createLinearClampSampler(device)) {
    const LutDimensions& n = parameters_.lut;
    const glm::ivec3 packed = n.packed3d();
    tables_.netDensity = createColorTexture(device, n.netDensityZenith, n.netDensityHeight, DXGI_FORMAT_R32G32B32A32_FLOAT, kReadWrite);
    tables_.singleScattering = createTexture3D(device, packed.x, packed.y, packed.z, kTableFormat, kReadWrite);
    tables_.multipleScattering = createTexture3D(device, packed.x, packed.y, packed.z, kTableFormat, kReadWrite);
    tables_.ambientLight = createColorTexture(device, n.ambientLight, 1, kTableFormat, kReadWrite);
    tables_.highOrderScattering = createTexture3D(device, packed.x, packed.y, packed.z, kTableFormat, kReadWrite);
    sphereDirectionsView_ = createSphereDirectionsView(device, parameters_.sphereSamples);

    const auto slabs = [&](Stage stage, unsigned count, unsigned perUnit, int order) {
        for (unsigned first = 0; first < count; first += perUnit) units_.push_back({stage, first, std::min(first + perUnit, count), order});
    };
    const unsigned depth = static_cast<unsigned>(packed.z);
    slabs(Stage::NetDensity, static_cast<unsigned>(n.netDensityHeight), kNetDensityRowsPerUnit, 0);
    slabs(Stage::SingleScattering, depth, kScatteringSlicesPerUnit, 1);
    for (int order = 2; order <= parameters_.scatteringOrders; ++order) {
        slabs(Stage::ScatteredRadiance, depth, kScatteredRadianceSlicesPerUnit, order);
        slabs(Stage::ScatteringOrder, depth, kScatteringSlicesPerUnit, order);
    }
    slabs(Stage::Combine, depth, depth, parameters_.scatteringOrders);
    units_.push_back({Stage::AmbientLight, 0, 1, 0});
}

// The textures only computing needs, made on the first unit of work: tables loaded from files
// never need them. The high-order sum ends in the texture the last order writes, which is the
// table itself (order 1 only: the cleared one).
void ScatteringPrecomputation::allocateScratch() {
    const glm::ivec3 packed = parameters_.lut.packed3d();
    const int last = parameters_.scatteringOrders;
    const int result = last >= 2 ? (last + 1) % 2 : 0;
    highOrders_[result] = tables_.highOrderScattering;
    if (last < 2) return;
    highOrders_[1 - result] = createTexture3D(device_, packed.x, packed.y, packed.z, kTableFormat, kReadWrite);
    // J is radiance per metre, about 1e-7 in these units: below half float's normal range
    // (6e-5), where it would keep one or two bits. Float32 holds it.
    scattered_ = createTexture3D(device_, packed.x, packed.y, packed.z, DXGI_FORMAT_R32G32B32A32_FLOAT, kReadWrite);
    for (auto& texture : orders_) texture = createTexture3D(device_, packed.x, packed.y, packed.z, kTableFormat, kReadWrite);
}

void ScatteringPrecomputation::markComplete() {
    next_ = units_.size();
    releaseScratch();
}

void ScatteringPrecomputation::releaseScratch() {  // the tables keep their own references
    scattered_ = {};
    orders_[0] = orders_[1] = {};
    highOrders_[0] = highOrders_[1] = {};
}

std::string ScatteringPrecomputation::currentStage() const {
    if (done()) return "done";
    const Unit& u = units_[next_];
    switch (u.stage) {
        case Stage::NetDensity: return "net density";
        case Stage::SingleScattering: return "single scattering";
        case Stage::ScatteredRadiance: return "order " + std::to_string(u.order) + ": scattered radiance J";
        case Stage::ScatteringOrder: return "order " + std::to_string(u.order) + ": in-scattering";
        case Stage::Combine: return "multiple scattering";
        case Stage::AmbientLight: return "ambient sky light";
    }
    return {};
}

void ScatteringPrecomputation::run(ID3D11DeviceContext* context, ShaderLibrary& shaders, const Unit& unit) {
    atmosphere_.update(context, parameters_.constants());
    gpu::PrecomputeSliceConstants slab{};
    slab.range = glm::uvec4(unit.first, unit.end, 0u, 0u);
    slab_.update(context, slab);
    ID3D11Buffer* buffers[2] = {atmosphere_.get(), slab_.get()};
    context->CSSetConstantBuffers(0, 2, buffers);
    context->CSSetSamplers(0, 1, linearClamp_.GetAddressOf());
    const LutDimensions& n = parameters_.lut;
    const auto bind = [&](const ShaderKey& key, std::initializer_list<ID3D11ShaderResourceView*> inputs,
                          std::initializer_list<ID3D11UnorderedAccessView*> outputs) {
        context->CSSetShader(shaders.computeShader(key), nullptr, 0);
        context->CSSetShaderResources(0, static_cast<UINT>(inputs.size()), inputs.begin());
        context->CSSetUnorderedAccessViews(0, static_cast<UINT>(outputs.size()), outputs.begin(), nullptr);
    };
    const auto dispatchTable = [&] {
        context->Dispatch(groups(static_cast<unsigned>(n.height), kScatteringGroup[0]), groups(static_cast<unsigned>(n.viewZenith), kScatteringGroup[1]),
                          groups(unit.end - unit.first, kScatteringGroup[2]));
    };
    // Order n reads order n - 1 (the single scattering table for n = 2) and writes orders_[n % 2];
    // the high-order sum goes from highOrders_[n % 2] to highOrders_[(n + 1) % 2].
    const int o = unit.order;
    switch (unit.stage) {
        case Stage::NetDensity:
            bind(kNetDensity, {}, {tables_.netDensity.uav.Get()});
            context->Dispatch(groups(static_cast<unsigned>(n.netDensityZenith), kNetDensityGroup[0]), groups(unit.end - unit.first, kNetDensityGroup[1]), 1);
            break;
        case Stage::SingleScattering:
            bind(kSingleScattering, {tables_.netDensity.srv.Get()}, {tables_.singleScattering.uav.Get()});
            if (unit.first == 0) {  // before order 2 the high-order sum is zero
                const float zero[4] = {};
                context->ClearUnorderedAccessViewFloat(highOrders_[0].uav.Get(), zero);
            }
            dispatchTable();
            break;
        case Stage::ScatteredRadiance: {
            ID3D11ShaderResourceView* previous = o == 2 ? tables_.singleScattering.srv.Get() : orders_[(o - 1) % 2].srv.Get();
            bind(kScatteredRadiance, {previous, sphereDirectionsView_.Get()}, {scattered_.uav.Get()});
            dispatchTable();
            break;
        }
        case Stage::ScatteringOrder:
            bind(kScatteringOrder, {scattered_.srv.Get(), nullptr, highOrders_[o % 2].srv.Get()},
                 {orders_[o % 2].uav.Get(), highOrders_[(o + 1) % 2].uav.Get()});
            dispatchTable();
            break;
        case Stage::Combine: {
            const Texture3D& high = o >= 2 ? highOrders_[(o + 1) % 2] : highOrders_[0];
            bind(kCombine, {tables_.singleScattering.srv.Get(), nullptr, high.srv.Get()}, {tables_.multipleScattering.uav.Get()});
            dispatchTable();
            break;
        }
        case Stage::AmbientLight:
            bind(kAmbientLight, {tables_.multipleScattering.srv.Get(), sphereDirectionsView_.Get()}, {tables_.ambientLight.uav.Get()});
            context->Dispatch(groups(static_cast<unsigned>(n.ambientLight), kAmbientGroup), 1, 1);
            break;
    }
    ID3D11UnorderedAccessView* noUavs[2] = {};
    ID3D11ShaderResourceView* noSrvs[3] = {};
    context->CSSetUnorderedAccessViews(0, 2, noUavs, nullptr);
    context->CSSetShaderResources(0, 3, noSrvs);
}

bool ScatteringPrecomputation::step(ID3D11DeviceContext* context, ShaderLibrary& shaders) {
    if (done()) return false;
    if (next_ == 0) allocateScratch();
    run(context, shaders, units_[next_++]);
    if (done()) releaseScratch();
    return true;
}

void ScatteringPrecomputation::runAll(ID3D11DeviceContext* context, ShaderLibrary& shaders) {
    const LutDimensions& n = parameters_.lut;
    char what[200];
    std::snprintf(what, sizeof(what), "net density %dx%d, scattering %dx%dx%dx%d with orders up to %d, ambient light %d",
                  n.netDensityZenith, n.netDensityHeight, n.height, n.viewZenith, n.sunZenith, n.sunView, parameters_.scatteringOrders,
                  n.ambientLight);
    log::info(std::string("atmosphere: pre-computing ") + what);
    runAllUnits(context, "atmosphere: ",
                {[&] { return step(context, shaders); }, [&] { return progress(); }, [&] { return currentStage(); }});
}

}  // namespace firmament
