// Fuzz target: the terrain's height-field cache file, read as the program reads it
// (readHeightFieldFile: never throws; a field it accepts has the parameters' size).
#include "FuzzSupport.h"

#include "core/FileIO.h"
#include "terrain/HeightFieldFile.h"

#include <unistd.h>

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, size_t size) {
    using namespace firmament;
    static const std::filesystem::path file =
        std::filesystem::temp_directory_path() / ("firmament-fuzz-heights-" + std::to_string(getpid()) + ".exr");
    TerrainGeneratorParameters parameters;
    parameters.size = 8;  // the seeds are made for these parameters (fuzz_write_seeds)
    try {
        writeFileBytes(file, fuzz::bytesOf(data, size));
        std::string why;
        const std::optional<HeightField> field = readHeightFieldFile(file, parameters, why);
        FUZZ_CHECK(field.has_value() == why.empty());
        if (field) FUZZ_CHECK(field->size() == parameters.size);
    } catch (const std::exception& e) {
        fuzz::fail("readHeightFieldFile threw", e.what());
    }
    return 0;
}
