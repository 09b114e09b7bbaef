#include "atmosphere/PrecomputationSupport.h"

#include "core/Log.h"
#include "gpu/Hresult.h"

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdio>

namespace firmament {

ComPtr<ID3D11SamplerState> createLinearClampSampler(ID3D11Device* device) {
    D3D11_SAMPLER_DESC desc{};
    desc.Filter = D3D11_FILTER_MIN_MAG_MIP_LINEAR;
    desc.AddressU = desc.AddressV = desc.AddressW = D3D11_TEXTURE_ADDRESS_CLAMP;
    desc.MaxLOD = D3D11_FLOAT32_MAX;
    ComPtr<ID3D11SamplerState> sampler;
    check(device->CreateSamplerState(&desc, &sampler), "CreateSamplerState (linear clamp)");
    return sampler;
}

std::vector<glm::vec4> uniformSphereDirections(int count) {
    const double goldenAngle = 3.14159265358979323846 * (3.0 - std::sqrt(5.0));
    std::vector<glm::vec4> directions;
    for (int i = 0; i < count; ++i) {
        const double y = 1.0 - (2.0 * i + 1.0) / count;
        const double r = std::sqrt(std::max(0.0, 1.0 - y * y));
        directions.emplace_back(static_cast<float>(r * std::cos(goldenAngle * i)), static_cast<float>(y),
                                static_cast<float>(r * std::sin(goldenAngle * i)), 0.0f);
    }
    return directions;
}

ComPtr<ID3D11ShaderResourceView> createSphereDirectionsView(ID3D11Device* device, int count) {
    const auto directions = uniformSphereDirections(count);
    D3D11_BUFFER_DESC desc{};
    desc.ByteWidth = static_cast<UINT>(directions.size() * sizeof(glm::vec4));
    desc.Usage = D3D11_USAGE_IMMUTABLE;
    desc.BindFlags = D3D11_BIND_SHADER_RESOURCE;
    desc.MiscFlags = D3D11_RESOURCE_MISC_BUFFER_STRUCTURED;
    desc.StructureByteStride = sizeof(glm::vec4);
    const D3D11_SUBRESOURCE_DATA data{directions.data(), 0, 0};
    ComPtr<ID3D11Buffer> buffer;
    check(device->CreateBuffer(&desc, &data, &buffer), "CreateBuffer (sphere directions)");
    ComPtr<ID3D11ShaderResourceView> view;
    check(device->CreateShaderResourceView(buffer.Get(), nullptr, &view), "CreateShaderResourceView (sphere directions)");
    return view;
}

void waitForGpu(ID3D11DeviceContext* context) {
    D3D11_QUERY_DESC desc{D3D11_QUERY_EVENT, 0};
    ComPtr<ID3D11Device> device;
    context->GetDevice(&device);
    ComPtr<ID3D11Query> finished;
    check(device->CreateQuery(&desc, &finished), "CreateQuery (event)");
    context->End(finished.Get());
    BOOL signalled = FALSE;
    while (context->GetData(finished.Get(), &signalled, sizeof(signalled), 0) != S_OK) Sleep(1);
}

void runAllUnits(ID3D11DeviceContext* context, const std::string& logPrefix, const UnitsOfWork& work) {
    const auto start = std::chrono::steady_clock::now();
    int reported = 0;
    while (work.step()) {
        const int percent = static_cast<int>(work.progress() * 100.0);
        if (percent >= reported + 10 || percent >= 100) {
            context->Flush();
            log::info(logPrefix + std::to_string(percent) + "%, next: " + work.nextStage());
            reported = percent;
        }
    }
    waitForGpu(context);  // so that the time said is the pre-computation's
    const double seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
    char what[100];
    std::snprintf(what, sizeof(what), "tables ready in %.2f s", seconds);
    log::info(logPrefix + what);
}

}  // namespace firmament
