#include "tables/TableFiles.h"

#include <cstring>

namespace firmament {

std::string tableKey(const std::string& description, ShaderLibrary& shaders, std::span<const ShaderKey> precomputeShaders) {
    std::uint64_t hash = fnv1a(description.data(), description.size());
    for (const ShaderKey& key : precomputeShaders) {
        const auto& bytecode = shaders.bytecode(key);
        hash = fnv1a(bytecode.data(), bytecode.size(), hash);
    }
    return hexKey(hash);
}

FloatRgbaImage floatRgbaImage(const ReadbackImage& texels) {
    FloatRgbaImage image{texels.width, texels.height, std::vector<float>(texels.bytes.size() / 4)};
    std::memcpy(image.rgba.data(), texels.bytes.data(), texels.bytes.size());
    return image;
}

}  // namespace firmament
