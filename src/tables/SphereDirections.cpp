#include "tables/SphereDirections.h"

#include "gpu/Hresult.h"

#include <algorithm>
#include <cmath>

namespace firmament {

using Microsoft::WRL::ComPtr;

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

}  // namespace firmament
