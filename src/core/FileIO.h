#pragma once
// Whole-file reads and writes that throw Error with the path and the reason.
//
// Every file the program writes (captures, table and height-field caches, exports, the state
// file, recorded flights, benchmark results) is replaced whole or not at all: the bytes go to a
// temporary file beside the target, which is flushed to the disk, closed and then renamed over
// the target. A full disk or a read-only folder is an Error naming the file and the reason, with
// the old file as it was and no temporary file left; a crash in the middle leaves the old file
// too, and at worst a stray "<name>.part-<hex>" beside it (docs/reliability.md).
#include <cstdint>
#include <filesystem>
#include <span>
#include <string_view>
#include <vector>

namespace firmament {

std::vector<std::uint8_t> readFileBytes(const std::filesystem::path& path);
void writeFileBytes(const std::filesystem::path& path, std::span<const std::uint8_t> bytes);
void writeFileText(const std::filesystem::path& path, std::string_view text);

// Creates the parent folders of `path` and checks that a file can be written there, so
// that a bad output path is reported before any long work starts.
void ensureWritable(const std::filesystem::path& path);

}  // namespace firmament
