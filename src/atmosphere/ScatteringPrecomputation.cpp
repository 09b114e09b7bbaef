#include "atmosphere/ScatteringPrecomputation.h"

#include "core/Log.h"
#include "gpu/Hresult.h"

#include <algorithm>
#include <chrono>
#include <cstdio>

namespace firmament {

namespace {
const ShaderKey kNetDensity{"atmosphere/precompute_net_density.hlsl", "main", "cs_5_0", {}};
const ShaderKey kSingleScattering{"atmosphere/precompute_single_scattering.hlsl", "main", "cs_5_0", {}};

// Thread-group sizes of the two shaders.
constexpr unsigned kNetDensityGroup[2] = {8, 8};
constexpr unsigned kScatteringGroup[3] = {4, 8, 4};
// Work per unit: about 0.1-0.2 s each on the WARP device at the full resolution.
constexpr unsigned kNetDensityRowsPerUnit = 128;
constexpr unsigned kScatteringSlicesPerUnit = 64;

unsigned groups(unsigned count, unsigned size) { return (count + size - 1) / size; }
}  // namespace

ComPtr<ID3D11SamplerState> createLinearClampSampler(ID3D11Device* device) {
    D3D11_SAMPLER_DESC desc{};
    desc.Filter = D3D11_FILTER_MIN_MAG_MIP_LINEAR;
    desc.AddressU = desc.AddressV = desc.AddressW = D3D11_TEXTURE_ADDRESS_CLAMP;
    desc.MaxLOD = D3D11_FLOAT32_MAX;
    ComPtr<ID3D11SamplerState> sampler;
    check(device->CreateSamplerState(&desc, &sampler), "CreateSamplerState (linear clamp)");
    return sampler;
}

ScatteringPrecomputation::ScatteringPrecomputation(ID3D11Device* device, const AtmosphereParameters& parameters)
    : parameters_(parameters), atmosphere_(device), slab_(device), linearClamp_(createLinearClampSampler(device)) {
    const LutDimensions& n = parameters_.lut;
    tables_.netDensity = createColorTexture(device, n.netDensityZenith, n.netDensityHeight, DXGI_FORMAT_R32G32B32A32_FLOAT,
                                            D3D11_BIND_SHADER_RESOURCE | D3D11_BIND_UNORDERED_ACCESS);
    const glm::ivec3 packed = n.packed3d();
    tables_.singleScattering = createTexture3D(device, packed.x, packed.y, packed.z, DXGI_FORMAT_R16G16B16A16_FLOAT,
                                               D3D11_BIND_SHADER_RESOURCE | D3D11_BIND_UNORDERED_ACCESS);
    for (unsigned row = 0; row < static_cast<unsigned>(n.netDensityHeight); row += kNetDensityRowsPerUnit)
        units_.push_back({Stage::NetDensity, row, std::min(row + kNetDensityRowsPerUnit, static_cast<unsigned>(n.netDensityHeight))});
    for (unsigned z = 0; z < static_cast<unsigned>(packed.z); z += kScatteringSlicesPerUnit)
        units_.push_back({Stage::SingleScattering, z, std::min(z + kScatteringSlicesPerUnit, static_cast<unsigned>(packed.z))});
}

std::string ScatteringPrecomputation::currentStage() const {
    if (done()) return "done";
    return units_[next_].stage == Stage::NetDensity ? "net density" : "single scattering";
}

void ScatteringPrecomputation::run(ID3D11DeviceContext* context, ShaderLibrary& shaders, const Unit& unit) {
    atmosphere_.update(context, parameters_.constants());
    gpu::PrecomputeSliceConstants slab{};
    slab.range = glm::uvec4(unit.first, unit.end, 0u, 0u);
    slab_.update(context, slab);
    ID3D11Buffer* buffers[2] = {atmosphere_.get(), slab_.get()};
    context->CSSetConstantBuffers(0, 2, buffers);
    const LutDimensions& n = parameters_.lut;
    if (unit.stage == Stage::NetDensity) {
        context->CSSetShader(shaders.computeShader(kNetDensity), nullptr, 0);
        context->CSSetUnorderedAccessViews(0, 1, tables_.netDensity.uav.GetAddressOf(), nullptr);
        context->Dispatch(groups(static_cast<unsigned>(n.netDensityZenith), kNetDensityGroup[0]),
                          groups(unit.end - unit.first, kNetDensityGroup[1]), 1);
    } else {
        context->CSSetShader(shaders.computeShader(kSingleScattering), nullptr, 0);
        context->CSSetShaderResources(0, 1, tables_.netDensity.srv.GetAddressOf());
        context->CSSetSamplers(0, 1, linearClamp_.GetAddressOf());
        context->CSSetUnorderedAccessViews(0, 1, tables_.singleScattering.uav.GetAddressOf(), nullptr);
        context->Dispatch(groups(static_cast<unsigned>(n.height), kScatteringGroup[0]),
                          groups(static_cast<unsigned>(n.viewZenith), kScatteringGroup[1]), groups(unit.end - unit.first, kScatteringGroup[2]));
    }
    ID3D11UnorderedAccessView* noUav = nullptr;
    ID3D11ShaderResourceView* noSrv = nullptr;
    context->CSSetUnorderedAccessViews(0, 1, &noUav, nullptr);
    context->CSSetShaderResources(0, 1, &noSrv);
}

bool ScatteringPrecomputation::step(ID3D11DeviceContext* context, ShaderLibrary& shaders) {
    if (done()) return false;
    run(context, shaders, units_[next_++]);
    return true;
}

void ScatteringPrecomputation::runAll(ID3D11DeviceContext* context, ShaderLibrary& shaders) {
    const LutDimensions& n = parameters_.lut;
    char what[160];
    std::snprintf(what, sizeof(what), "net density %dx%d, single scattering %dx%dx%dx%d", n.netDensityZenith, n.netDensityHeight,
                  n.height, n.viewZenith, n.sunZenith, n.sunView);
    log::info(std::string("atmosphere: pre-computing ") + what);
    const auto start = std::chrono::steady_clock::now();
    int reported = 0;
    while (step(context, shaders)) {
        const int percent = static_cast<int>(progress() * 100.0);
        if (percent >= reported + 25 || done()) {
            context->Flush();
            log::info("atmosphere: " + std::to_string(percent) + "% (" + currentStage() + ")");
            reported = percent;
        }
    }
    // Wait for the GPU, so that the time said is the pre-computation's.
    D3D11_QUERY_DESC desc{D3D11_QUERY_EVENT, 0};
    ComPtr<ID3D11Device> device;
    context->GetDevice(&device);
    ComPtr<ID3D11Query> finished;
    check(device->CreateQuery(&desc, &finished), "CreateQuery (event)");
    context->End(finished.Get());
    BOOL signalled = FALSE;
    while (context->GetData(finished.Get(), &signalled, sizeof(signalled), 0) != S_OK) Sleep(1);
    const double seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
    std::snprintf(what, sizeof(what), "atmosphere: tables ready in %.2f s", seconds);
    log::info(what);
}

}  // namespace firmament
