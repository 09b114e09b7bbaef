#pragma once
// GPU test fixture: the WARP device (Wine's own device under Wine) and shader libraries of
// the test shaders and of the program's shaders.
#include "gpu/Device.h"
#include "gpu/PrecompiledShaders.h"
#include "gpu/ShaderLibrary.h"
#include "support/TestPaths.h"

#include <gtest/gtest.h>

#include <cstring>
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
