#pragma once
// GPU test fixture: the WARP device (Wine's own device under Wine) and shader libraries of
// the test shaders and of the program's shaders.
#include "gpu/Device.h"
#include "gpu/PrecompiledShaders.h"
#include "gpu/Readback.h"
#include "gpu/ShaderLibrary.h"
#include "support/TestPaths.h"

#include <gtest/gtest.h>

#include <glm/glm.hpp>

#include <cstring>
#include <initializer_list>
#include <memory>
#include <vector>

namespace firmament::test {

class WarpDevice : public ::testing::Test {
protected:
    void SetUp() override {
        gpu = std::make_unique<Device>(DeviceOptions{DriverType::Warp, std::nullopt, false});
        testShaderLibrary = std::make_unique<ShaderLibrary>(gpu->device(), std::make_unique<PrecompiledShaders>(testShaders()));
        productShaderLibrary =
            std::make_unique<ShaderLibrary>(gpu->device(), std::make_unique<PrecompiledShaders>(productShaders()));
    }

    ID3D11Device* device() const { return gpu->device(); }
    ID3D11DeviceContext* context() const { return gpu->context(); }

    // A structured buffer holding `values`, readable by shaders (SRV) or writable (UAV).
    template <typename T>
    ComPtr<ID3D11Buffer> structuredBuffer(const std::vector<T>& values, bool writable) {
        D3D11_BUFFER_DESC desc{};
        desc.ByteWidth = static_cast<UINT>(values.size() * sizeof(T));
        desc.Usage = D3D11_USAGE_DEFAULT;
        desc.BindFlags = writable ? D3D11_BIND_UNORDERED_ACCESS : D3D11_BIND_SHADER_RESOURCE;
        desc.MiscFlags = D3D11_RESOURCE_MISC_BUFFER_STRUCTURED;
        desc.StructureByteStride = sizeof(T);
        D3D11_SUBRESOURCE_DATA data{values.data(), 0, 0};
        ComPtr<ID3D11Buffer> buffer;
        EXPECT_HRESULT_SUCCEEDED(device()->CreateBuffer(&desc, &data, &buffer));
        return buffer;
    }

    // Runs one compute shader over `input` (t0) into a fresh output buffer of `outputCount`
    // elements (u0, filled with `fill` first) with `groups` thread groups; returns the output.
    template <typename In, typename Out>
    std::vector<Out> runCompute(const ShaderKey& key, const std::vector<In>& input, size_t outputCount, Out fill,
                                UINT groups) {
        auto inputBuffer = structuredBuffer(input, false);
        auto outputBuffer = structuredBuffer(std::vector<Out>(outputCount, fill), true);
        ComPtr<ID3D11ShaderResourceView> srv;
        ComPtr<ID3D11UnorderedAccessView> uav;
        EXPECT_HRESULT_SUCCEEDED(device()->CreateShaderResourceView(inputBuffer.Get(), nullptr, &srv));
        EXPECT_HRESULT_SUCCEEDED(device()->CreateUnorderedAccessView(outputBuffer.Get(), nullptr, &uav));
        context()->CSSetShader(testShaderLibrary->computeShader(key), nullptr, 0);
        context()->CSSetShaderResources(0, 1, srv.GetAddressOf());
        context()->CSSetUnorderedAccessViews(0, 1, uav.GetAddressOf(), nullptr);
        context()->Dispatch(groups, 1, 1);
        return asVector<Out>(readBuffer(device(), context(), outputBuffer.Get()));
    }

    // Runs a probe shader of the test library (one thread per query, 64 to a group): queries
    // at t0, `tables` from t1 on, constant buffers from b0, a linear clamp sampler at s0, and
    // one float4 result per query at u0.
    template <typename Query>
    std::vector<glm::vec4> runProbe(const ShaderKey& key, const std::vector<Query>& queries, std::initializer_list<ID3D11Buffer*> constants,
                                    std::initializer_list<ID3D11ShaderResourceView*> tables, ID3D11SamplerState* sampler) {
        auto input = structuredBuffer(queries, false);
        auto output = structuredBuffer(std::vector<glm::vec4>(queries.size(), glm::vec4(-1.0f)), true);
        ComPtr<ID3D11ShaderResourceView> inputView;
        ComPtr<ID3D11UnorderedAccessView> outputView;
        EXPECT_HRESULT_SUCCEEDED(device()->CreateShaderResourceView(input.Get(), nullptr, &inputView));
        EXPECT_HRESULT_SUCCEEDED(device()->CreateUnorderedAccessView(output.Get(), nullptr, &outputView));
        std::vector<ID3D11ShaderResourceView*> views{inputView.Get()};
        views.insert(views.end(), tables.begin(), tables.end());
        context()->CSSetShader(testShaderLibrary->computeShader(key), nullptr, 0);
        context()->CSSetConstantBuffers(0, static_cast<UINT>(constants.size()), constants.begin());
        context()->CSSetShaderResources(0, static_cast<UINT>(views.size()), views.data());
        context()->CSSetSamplers(0, 1, &sampler);
        context()->CSSetUnorderedAccessViews(0, 1, outputView.GetAddressOf(), nullptr);
        context()->Dispatch(static_cast<UINT>((queries.size() + 63) / 64), 1, 1);
        ID3D11UnorderedAccessView* none = nullptr;
        context()->CSSetUnorderedAccessViews(0, 1, &none, nullptr);
        const std::vector<ID3D11ShaderResourceView*> noViews(views.size(), nullptr);
        context()->CSSetShaderResources(0, static_cast<UINT>(noViews.size()), noViews.data());
        return asVector<glm::vec4>(readBuffer(device(), context(), output.Get()));
    }

    template <typename T>
    std::vector<T> asVector(const std::vector<std::uint8_t>& bytes) {
        std::vector<T> out(bytes.size() / sizeof(T));
        std::memcpy(out.data(), bytes.data(), out.size() * sizeof(T));
        return out;
    }

    std::unique_ptr<Device> gpu;
    std::unique_ptr<ShaderLibrary> testShaderLibrary;
    std::unique_ptr<ShaderLibrary> productShaderLibrary;
};

}  // namespace firmament::test
