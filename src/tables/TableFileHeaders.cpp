#include "tables/TableFileHeaders.h"

#include <cstdio>

namespace firmament {

std::uint64_t fnv1a(const void* data, size_t size, std::uint64_t hash) {
    const auto* bytes = static_cast<const std::uint8_t*>(data);
    for (size_t i = 0; i < size; ++i) hash = (hash ^ bytes[i]) * 0x100000001b3ull;
    return hash;
}

std::string hexKey(std::uint64_t hash) {
    char hex[17];
    std::snprintf(hex, sizeof(hex), "%016llx", static_cast<unsigned long long>(hash));
    return hex;
}

std::string tableKey(const std::string& description) { return hexKey(fnv1a(description.data(), description.size())); }

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
