#include "tables/SphereDirections.h"

#include "gpu/Buffers.h"

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
    return createStructuredBuffer(device, static_cast<unsigned>(directions.size()), sizeof(glm::vec4), directions.data(), "sphere directions").srv;
}

}  // namespace firmament
