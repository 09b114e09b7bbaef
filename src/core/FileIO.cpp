#include "core/FileIO.h"

#include "core/Error.h"

#include <cerrno>
#include <cstdio>
#include <fstream>
#include <random>
#include <system_error>

// The one platform seam of this file: flushing a file to the disk before the rename.
#ifdef _WIN32
#include <io.h>  // _commit, _fileno
#else
#include <unistd.h>  // fsync, fileno
#endif

namespace firmament {

namespace {

// The temporary file's name for `path`: beside it (a rename stays on one file system), with a
// random suffix of its own (two processes may write the same cache file at once).
std::filesystem::path temporaryPathFor(const std::filesystem::path& path) {
    std::random_device entropy;
    const std::uint64_t token = (static_cast<std::uint64_t>(entropy()) << 32) ^ entropy();
    char suffix[32];
    std::snprintf(suffix, sizeof(suffix), ".part-%016llx", static_cast<unsigned long long>(token));
    return std::filesystem::path(path).concat(suffix);
}

// The C library's reason for the last failure ("No space left on device").
std::string lastError() { return std::generic_category().message(errno); }

std::FILE* openForWriting(const std::filesystem::path& path) {
#ifdef _WIN32
    std::FILE* file = nullptr;
    return _wfopen_s(&file, path.c_str(), L"wb") == 0 ? file : nullptr;
#else
    return std::fopen(path.c_str(), "wb");
#endif
}

// Flushes the C library's buffer and then the operating system's to the disk, so that the
// rename that follows never exposes a file whose blocks are not written yet.
bool flushToDisk(std::FILE* file) {
    if (std::fflush(file) != 0) return false;
#ifdef _WIN32
    return _commit(_fileno(file)) == 0;
#else
    return fsync(fileno(file)) == 0;
#endif
}

void removeQuietly(const std::filesystem::path& path) {
    std::error_code ignored;
    std::filesystem::remove(path, ignored);
}

// Renames the finished temporary file over the target (on Windows too: MoveFileEx with
// MOVEFILE_REPLACE_EXISTING under std::filesystem::rename), or removes it and throws.
void replaceWith(const std::filesystem::path& temporary, const std::filesystem::path& path) {
    std::error_code ec;
    std::filesystem::rename(temporary, path, ec);
    if (ec) {
        removeQuietly(temporary);
        throw Error("cannot write '" + path.string() + "': cannot replace it with '" + temporary.string() + "': " + ec.message());
    }
}

}  // namespace

std::vector<std::uint8_t> readFileBytes(const std::filesystem::path& path) {
    std::ifstream file(path, std::ios::binary);
    if (!file) throw Error("cannot open '" + path.string() + "' for reading");
    file.seekg(0, std::ios::end);
    const auto size = static_cast<std::streamoff>(file.tellg());
    file.seekg(0, std::ios::beg);
    if (size < 0) throw Error("cannot read '" + path.string() + "' (not a regular file)");
    std::vector<std::uint8_t> bytes(static_cast<size_t>(size));
    if (size > 0 && !file.read(reinterpret_cast<char*>(bytes.data()), size))
        throw Error("cannot read '" + path.string() + "'");
    return bytes;
}

void writeFileBytes(const std::filesystem::path& path, std::span<const std::uint8_t> bytes) {
    const auto temporary = temporaryPathFor(path);
    std::FILE* file = openForWriting(temporary);
    if (!file) throw Error("cannot write '" + path.string() + "': cannot create a file in its folder: " + lastError());
    const bool written = bytes.empty() || std::fwrite(bytes.data(), 1, bytes.size(), file) == bytes.size();
    const bool flushed = written && flushToDisk(file);
    const std::string why = written && flushed ? std::string() : lastError();
    const bool closed = std::fclose(file) == 0;
    if (!written || !flushed || !closed) {
        removeQuietly(temporary);
        throw Error("cannot write '" + path.string() + "': " + (why.empty() ? lastError() : why));
    }
    replaceWith(temporary, path);
}

void writeFileText(const std::filesystem::path& path, std::string_view text) {
    writeFileBytes(path, std::span(reinterpret_cast<const std::uint8_t*>(text.data()), text.size()));
}

void ensureWritable(const std::filesystem::path& path) {
    std::error_code ec;
    const auto parent = path.has_parent_path() ? path.parent_path() : std::filesystem::path(".");
    std::filesystem::create_directories(parent, ec);
    if (ec) throw Error("cannot create the folder '" + parent.string() + "': " + ec.message());
    if (std::filesystem::is_directory(path, ec)) throw Error("cannot write to '" + path.string() + "': it is a folder");
    // A probe of its own, so that the file itself (if there is one) is never opened for writing.
    const auto probe = temporaryPathFor(path);
    std::FILE* file = openForWriting(probe);
    if (!file) throw Error("cannot write to '" + path.string() + "': " + lastError());
    std::fclose(file);
    removeQuietly(probe);
}

}  // namespace firmament
