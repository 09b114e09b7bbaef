// Writes the fuzz targets' seed corpora (tests/fuzz/corpus/<target>/) from the program's own
// writers, so that every seed is a valid file of today's format: tools/fuzz --write-seeds.
// The JSON seeds for flights and the command line are kept by hand beside them.
#include "app/FlightPath.h"
#include "core/ExrImage.h"
#include "core/FileIO.h"
#include "core/PngImage.h"
#include "core/SettingsJson.h"
#include "settings/State.h"
#include "tables/TableFileHeaders.h"
#include "terrain/HeightFieldFile.h"

#include <cstdio>
#include <string>
#include <vector>

using namespace firmament;
namespace fs = std::filesystem;

namespace {

void write(const fs::path& corpus, const std::string& target, const std::string& name, std::span<const std::uint8_t> bytes) {
    fs::create_directories(corpus / target);
    writeFileBytes(corpus / target / name, bytes);
}

void writeText(const fs::path& corpus, const std::string& target, const std::string& name, const std::string& text) {
    write(corpus, target, name, std::span(reinterpret_cast<const std::uint8_t*>(text.data()), text.size()));
}

}  // namespace

int main(int argc, char** argv) {
    if (argc != 2) {
        std::fprintf(stderr, "usage: fuzz_write_seeds CORPUS_FOLDER\n");
        return 2;
    }
    const fs::path corpus = argv[1];
    try {
        State state;
        writeText(corpus, "state_file", "default.json", stateToJson(state).dump(2));
        state.storeBookmark(3);
        state.camera.position.y = 40000.0f;
        writeText(corpus, "state_file", "bookmark.json", stateToJson(state).dump(2));
        writeText(corpus, "settings_json", "default.json", settingsToJson(State().sections()).dump(2));

        // EXR files as the caches and captures write them.
        const fs::path scratch = fs::temp_directory_path() / "firmament-fuzz-seed.exr";
        const auto exrSeed = [&](const std::string& target, const std::string& name, auto&& writeIt) {
            writeIt(scratch);
            write(corpus, target, name, readFileBytes(scratch));
            fs::remove(scratch);
        };
        exrSeed("exr_table", "table-rgba.exr", [](const fs::path& p) {
            writeExr(p, FloatRgbaImage{4, 2, std::vector<float>(32, 0.5f)}, {{"firmament.lut.key", std::string("0123456789abcdef")}});
        });
        exrSeed("exr_table", "capture-half.exr", [](const fs::path& p) {
            writeExr(p, HalfRgbaImage{2, 2, std::vector<std::uint16_t>(16, 0x3c00)},
                     {{"firmament.camera.position", glm::vec3(0.0f, 1500.0f, 0.0f)}, {"firmament.frame", 3}});
        });
        TerrainGeneratorParameters parameters;
        parameters.size = 8;  // as fuzz_height_field reads them
        std::vector<float> heights(64);
        for (size_t i = 0; i < heights.size(); ++i) heights[i] = static_cast<float>(i) * 10.0f;
        exrSeed("height_field", "valid.exr", [&](const fs::path& p) {
            writeExr(p, FloatImage{8, 8, heights}, {{"firmament.lut.key", tableKey(parameters.describe())}});
        });
        exrSeed("height_field", "other-key.exr", [&](const fs::path& p) {
            writeExr(p, FloatImage{8, 8, heights}, {{"firmament.lut.key", std::string("ffffffffffffffff")}});
        });
        exrSeed("exr_table", "heights-y.exr", [&](const fs::path& p) { writeExr(p, FloatImage{8, 8, heights}, {}); });

        std::vector<std::uint8_t> pixels(3 * 2 * 4);
        for (size_t i = 0; i < pixels.size(); ++i) pixels[i] = static_cast<std::uint8_t>(i * 37);
        write(corpus, "png", "rgba-3x2.png", encodePng(Rgba8Image{3, 2, pixels}));
    } catch (const Error& e) {
        std::fprintf(stderr, "fuzz_write_seeds: %s\n", e.what());
        return 1;
    }
    return 0;
}
