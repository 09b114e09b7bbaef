#pragma once
// Tables cached on disk as OpenEXR files (both atmosphere models' look-up tables, the terrain's
// height field, the clouds' tables to come): the cache key, writing a file so that no reader
// ever sees half of it, and the header check that decides whether a file fits.
#include "core/ExrImage.h"
#include "gpu/ShaderLibrary.h"

#include <filesystem>
#include <span>
#include <string>

namespace firmament {

// A key for everything that shapes a set of tables: a 64-bit FNV-1a hash (stable across builds
// and platforms, unlike std::hash) of their description and of the pre-computation shaders'
// bytecode (an edited shader makes new tables), in hex.
std::string tableKey(const std::string& description, ShaderLibrary& shaders, std::span<const ShaderKey> precomputeShaders);
// The same key for data made on the CPU alone (the terrain's height field): the description's hash.
std::string tableKey(const std::string& description);

// Writes through a temporary file of this process's own, then renames it. Throws Error.
void writeTableAtomically(const std::filesystem::path& path, const HalfRgbaImage& image, const ExrAttributes& attributes);
void writeTableAtomically(const std::filesystem::path& path, const FloatRgbaImage& image, const ExrAttributes& attributes);
void writeTableAtomically(const std::filesystem::path& path, const FloatImage& image, const ExrAttributes& attributes);

// Empty when the header's firmament.lut.key is `key` and the file is width x height; else why not.
std::string checkTableHeader(const ExrAttributes& attributes, const std::string& key, int width, int height, int fileWidth, int fileHeight);

}  // namespace firmament
