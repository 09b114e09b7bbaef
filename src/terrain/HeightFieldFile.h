#pragma once
// Where the terrain's height field comes from: generated at the first run and kept in the cache
// folder (the atmosphere's tables' folder) as a one-channel float OpenEXR file,
// terrain-<key>-heights.exr, whose key hashes the generator's parameters. Chosen over a file in
// media/: the generator is the source (deterministic, unit-tested), a 16 MB binary in git would
// be a copy of it that could drift, and generating takes a few seconds once (docs/terrain.md).
#include "terrain/HeightField.h"
#include "terrain/TerrainGenerator.h"

#include <filesystem>
#include <optional>
#include <string>

namespace firmament {

// Reads the cached field when it is there and valid, else generates it (logging the time) and
// caches it. A cache that cannot be written is a warning; without a folder nothing is cached.
HeightField loadOrGenerateHeightField(const TerrainGeneratorParameters& parameters, const std::optional<std::filesystem::path>& cacheFolder);

// The cached field at `path` when it can be read and was made by these parameters; else nullopt,
// with the reason in `why`. Never throws for a bad file.
std::optional<HeightField> readHeightFieldFile(const std::filesystem::path& path, const TerrainGeneratorParameters& parameters, std::string& why);

// The cache file's name for these parameters.
std::string heightFieldFileName(const TerrainGeneratorParameters& parameters);

}  // namespace firmament
