#include "core/FileIO.h"

#include "core/Error.h"

#include <fstream>
#include <system_error>

namespace firmament {

std::vector<std::uint8_t> readFileBytes(const std::filesystem::path& path) {
    std::ifstream file(path, std::ios::binary);
    if (!file) throw Error("cannot open '" + path.string() + "' for reading");
    file.seekg(0, std::ios::end);
    const auto size = static_cast<std::streamoff>(file.tellg());
    file.seekg(0, std::ios::beg);
    std::vector<std::uint8_t> bytes(static_cast<size_t>(size));
    if (size > 0 && !file.read(reinterpret_cast<char*>(bytes.data()), size))
        throw Error("cannot read '" + path.string() + "'");
    return bytes;
}

void writeFileBytes(const std::filesystem::path& path, std::span<const std::uint8_t> bytes) {
    std::ofstream file(path, std::ios::binary | std::ios::trunc);
    if (!file) throw Error("cannot open '" + path.string() + "' for writing");
    file.write(reinterpret_cast<const char*>(bytes.data()), static_cast<std::streamsize>(bytes.size()));
    if (!file) throw Error("cannot write '" + path.string() + "'");
}

void ensureWritable(const std::filesystem::path& path) {
    std::error_code ec;
    const auto parent = path.has_parent_path() ? path.parent_path() : std::filesystem::path(".");
    std::filesystem::create_directories(parent, ec);
    if (ec) throw Error("cannot create the folder '" + parent.string() + "': " + ec.message());
    const bool existed = std::filesystem::exists(path, ec);
    {
        std::ofstream probe(path, std::ios::binary | std::ios::app);
        if (!probe) throw Error("cannot write to '" + path.string() + "'");
    }
    if (!existed) std::filesystem::remove(path, ec);
}

}  // namespace firmament
