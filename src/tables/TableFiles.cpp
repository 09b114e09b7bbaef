#include "tables/TableFiles.h"

#include "core/Error.h"

#include <windows.h>

#include <cstdint>
#include <cstdio>

namespace firmament {

namespace {

// FNV-1a, 64 bits: stable across builds and platforms, unlike std::hash.
std::uint64_t fnv1a(const void* data, size_t size, std::uint64_t hash) {
    const auto* bytes = static_cast<const std::uint8_t*>(data);
    for (size_t i = 0; i < size; ++i) hash = (hash ^ bytes[i]) * 0x100000001b3ull;
    return hash;
}

template <typename Image>
void writeAtomically(const std::filesystem::path& path, const Image& image, const ExrAttributes& attributes) {
    // A name of this process's own: two programs may cache the same tables at once.
    const auto temporary = std::filesystem::path(path).concat(".part" + std::to_string(GetCurrentProcessId()));
    writeExr(temporary, image, attributes);
    std::error_code ec;
    std::filesystem::rename(temporary, path, ec);
    if (ec) throw Error("cannot move '" + temporary.string() + "' to '" + path.string() + "': " + ec.message());
}

}  // namespace

std::string tableKey(const std::string& description, ShaderLibrary& shaders, std::span<const ShaderKey> precomputeShaders) {
    std::uint64_t hash = 0xcbf29ce484222325ull;
    hash = fnv1a(description.data(), description.size(), hash);
    for (const ShaderKey& key : precomputeShaders) {
        const auto& bytecode = shaders.bytecode(key);
        hash = fnv1a(bytecode.data(), bytecode.size(), hash);
    }
    char hex[17];
    std::snprintf(hex, sizeof(hex), "%016llx", static_cast<unsigned long long>(hash));
    return hex;
}

std::string tableKey(const std::string& description) {
    const std::uint64_t hash = fnv1a(description.data(), description.size(), 0xcbf29ce484222325ull);
    char hex[17];
    std::snprintf(hex, sizeof(hex), "%016llx", static_cast<unsigned long long>(hash));
    return hex;
}

void writeTableAtomically(const std::filesystem::path& path, const HalfRgbaImage& image, const ExrAttributes& attributes) {
    writeAtomically(path, image, attributes);
}
void writeTableAtomically(const std::filesystem::path& path, const FloatRgbaImage& image, const ExrAttributes& attributes) {
    writeAtomically(path, image, attributes);
}
void writeTableAtomically(const std::filesystem::path& path, const FloatImage& image, const ExrAttributes& attributes) {
    writeAtomically(path, image, attributes);
}

std::string checkTableHeader(const ExrAttributes& a, const std::string& key, int width, int height, int fileWidth, int fileHeight) {
    const auto found = a.find("firmament.lut.key");
    if (found == a.end() || !std::holds_alternative<std::string>(found->second)) return "it has no firmament.lut.key";
    if (std::get<std::string>(found->second) != key) return "its key differs (made for other parameters or shaders)";
    if (fileWidth != width || fileHeight != height)
        return "it is " + std::to_string(fileWidth) + "x" + std::to_string(fileHeight) + ", not " + std::to_string(width) + "x" +
               std::to_string(height);
    return {};
}

}  // namespace firmament
