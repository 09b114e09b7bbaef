#pragma once
// Whole-file reads and writes that throw Error with the path and the reason.
#include <cstdint>
#include <filesystem>
#include <span>
#include <vector>

namespace firmament {

std::vector<std::uint8_t> readFileBytes(const std::filesystem::path& path);
void writeFileBytes(const std::filesystem::path& path, std::span<const std::uint8_t> bytes);

// Creates the parent folders of `path` and checks that a file can be written there, so
// that a bad output path is reported before any long work starts.
void ensureWritable(const std::filesystem::path& path);

}  // namespace firmament
