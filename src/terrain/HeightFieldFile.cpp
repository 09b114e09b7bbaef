#include "terrain/HeightFieldFile.h"

#include "tables/TableFileHeaders.h"
#include "core/Error.h"
#include "core/Log.h"

#include <algorithm>
#include <chrono>

namespace firmament {

std::string heightFieldFileName(const TerrainGeneratorParameters& parameters) {
    return "terrain-" + tableKey(parameters.describe()) + "-heights.exr";
}

std::optional<HeightField> readHeightFieldFile(const std::filesystem::path& path, const TerrainGeneratorParameters& parameters, std::string& why) {
    try {
        FloatImageFile file = readFloatChannelExr(path);
        why = checkTableHeader(file.attributes, tableKey(parameters.describe()), parameters.size, parameters.size, file.image.width,
                               file.image.height);
        if (why.empty()) return HeightField(std::move(file.image.values), parameters.size, parameters.spacing);
    } catch (const Error& e) {
        why = e.what();
    }
    return std::nullopt;
}

HeightField loadOrGenerateHeightField(const TerrainGeneratorParameters& parameters, const std::optional<std::filesystem::path>& cacheFolder) {
    const std::string key = tableKey(parameters.describe());
    std::error_code ec;
    if (cacheFolder && std::filesystem::exists(*cacheFolder / heightFieldFileName(parameters), ec)) {
        const auto path = *cacheFolder / heightFieldFileName(parameters);
        std::string why;
        if (std::optional<HeightField> cached = readHeightFieldFile(path, parameters, why)) {
            log::info("terrain: height field loaded from " + path.string());
            return std::move(*cached);
        }
        log::warning("terrain: the cached height field " + path.string() + " cannot be used (" + why + "); generating the height field again");
    }
    log::info("terrain: generating the height field (" + parameters.describe() + ") ...");
    const auto start = std::chrono::steady_clock::now();
    std::vector<float> heights = generateHeights(parameters);
    const double seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
    const auto [low, high] = std::minmax_element(heights.begin(), heights.end());
    log::info("terrain: height field generated in " + std::to_string(seconds) + " s: " + std::to_string(parameters.size) + " x " +
              std::to_string(parameters.size) + " samples " + std::to_string(static_cast<int>(parameters.spacing)) + " m apart, heights " +
              std::to_string(static_cast<int>(*low)) + " .. " + std::to_string(static_cast<int>(*high)) + " m");
    if (cacheFolder) {
        try {
            std::filesystem::create_directories(*cacheFolder, ec);
            FloatImage image{parameters.size, parameters.size, heights};
            ExrAttributes attributes{{"firmament.lut.key", key},
                                     {"firmament.terrain.generator", parameters.describe()},
                                     {"firmament.terrain.spacing", static_cast<float>(parameters.spacing)}};
            writeExr(*cacheFolder / heightFieldFileName(parameters), image, attributes);
            log::info("terrain: height field saved to the cache in " + cacheFolder->string());
        } catch (const Error& e) {
            log::warning(std::string("terrain: the height field was not cached: ") + e.what());
        }
    }
    return HeightField(std::move(heights), parameters.size, parameters.spacing);
}

}  // namespace firmament
