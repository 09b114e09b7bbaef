// The atmosphere's table cache and --export-luts, from outside: a first run computes and caches
// the tables and exports them as self-describing EXR files; a corrupted cache file is reported,
// recomputed and replaced; a later run loads them.
#include "core/ExrImage.h"
#include "core/FileIO.h"
#include "support/Process.h"
#include "support/TestPaths.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <string>

namespace firmament::test {
namespace {

ProcessResult runWithCache(const std::filesystem::path& cache, std::vector<std::wstring> extra = {}) {
    std::vector<std::wstring> args{L"--headless", L"--frames", L"1", L"--resolution", L"32x32", L"--set",
                                   L"atmosphere.lutResolution=small (8x32x16x8)", L"--cache-dir", cache.wstring()};
    args.insert(args.end(), extra.begin(), extra.end());
    return runProcess(firmamentExe(), args);
}

std::vector<std::filesystem::path> filesIn(const std::filesystem::path& folder) {
    std::vector<std::filesystem::path> files;
    for (const auto& entry : std::filesystem::directory_iterator(folder)) files.push_back(entry.path());
    return files;
}

TEST(TableCache, ComputesCachesExportsRecoversAndLoads) {
    const auto folder = std::filesystem::temp_directory_path() / "firmament-table-cache-test";
    std::filesystem::remove_all(folder);
    const auto cache = folder / "cache", exported = folder / "exported";

    ProcessResult run = runWithCache(cache, {L"--export-luts", exported.wstring()});
    ASSERT_EQ(run.exitCode, 0u) << run.output;
    EXPECT_NE(run.output.find("saved to the cache"), std::string::npos) << run.output;
    EXPECT_NE(run.output.find("exported to"), std::string::npos) << run.output;
    // Net density, single, high-order and multiple scattering, ambient light; the terrain's
    // height field, generated at the first run into the same cache; the clouds' optical depth table.
    const auto cached = filesIn(cache);
    ASSERT_EQ(cached.size(), 7u);
    EXPECT_EQ(std::count_if(cached.begin(), cached.end(),
                            [](const std::filesystem::path& f) { return f.filename().string().find("cloud-optical-depth") != std::string::npos; }),
              1);
    EXPECT_EQ(std::count_if(cached.begin(), cached.end(),
                            [](const std::filesystem::path& f) { return f.filename().string().rfind("terrain-", 0) == 0; }),
              1);
    for (const char* name : {"net-density.exr", "single-scattering.exr", "high-order-scattering.exr", "multiple-scattering.exr",
                             "ambient-light.exr"})
        EXPECT_TRUE(std::filesystem::exists(exported / name)) << name;

    // The exported files describe themselves.
    const FloatExrFile density = readFloatExr(exported / "net-density.exr");
    EXPECT_EQ(density.image.width, 128);
    EXPECT_GT(density.image.rgba[0], 0.0f);
    const ExrFile scattering = readExr(exported / "single-scattering.exr");
    EXPECT_EQ(scattering.image.width, 2 * 8 * 16);  // (Rayleigh and Mie banks of altitude) x sun zenith tiles
    EXPECT_EQ(scattering.image.height, 32 * 8);  // view zenith x sun-view tiles
    for (const char* name : {"firmament.lut.name", "firmament.lut.dimensions", "firmament.lut.layout", "firmament.lut.parameterization",
                             "firmament.lut.key", "firmament.atmosphere.rayleighScattering", "firmament.atmosphere.earthRadius"})
        EXPECT_TRUE(scattering.attributes.count(name)) << name;
    EXPECT_EQ(std::get<std::string>(scattering.attributes.at("firmament.lut.dimensions")),
              "8 x 32 x 16 x 8 (altitude, view zenith, sun zenith, sun-view)");

    // Corrupt the cached single scattering: reported by name, recomputed, cached again.
    std::filesystem::path corrupted;
    for (const auto& file : filesIn(cache))
        if (file.filename().string().find("single-scattering") != std::string::npos) corrupted = file;
    ASSERT_FALSE(corrupted.empty());
    const std::string garbage = "not an EXR file";
    writeFileBytes(corrupted, std::span(reinterpret_cast<const std::uint8_t*>(garbage.data()), garbage.size()));
    run = runWithCache(cache);
    ASSERT_EQ(run.exitCode, 0u) << run.output;
    EXPECT_NE(run.output.find("cannot be used"), std::string::npos) << run.output;
    EXPECT_NE(run.output.find(corrupted.filename().string()), std::string::npos) << run.output;
    EXPECT_NE(run.output.find("saved to the cache"), std::string::npos) << run.output;
    EXPECT_NO_THROW(readExr(corrupted));

    run = runWithCache(cache);
    ASSERT_EQ(run.exitCode, 0u) << run.output;
    EXPECT_NE(run.output.find("loaded from the cache"), std::string::npos) << run.output;
    EXPECT_EQ(run.output.find("pre-computing"), std::string::npos) << run.output;

    // Another resolution is another key: computed, not loaded.
    run = runWithCache(cache, {L"--set", L"atmosphere.lutResolution=medium (16x64x32x8)"});
    ASSERT_EQ(run.exitCode, 0u) << run.output;
    EXPECT_NE(run.output.find("pre-computing"), std::string::npos) << run.output;
    EXPECT_EQ(filesIn(cache).size(), 12u);  // five more of the atmosphere; the clouds' table is the same
    std::filesystem::remove_all(folder);
}

// The terrain's height field: generated at the first run into the cache, loaded by the next,
// generated again (with a warning naming the file) when the cached file is damaged.
TEST(TableCache, TerrainHeightFieldIsGeneratedOnceAndRegeneratedWhenDamaged) {
    const auto folder = std::filesystem::temp_directory_path() / "firmament-terrain-cache";
    std::filesystem::remove_all(folder);
    const auto cache = folder / "cache";
    ProcessResult run = runWithCache(cache);
    ASSERT_EQ(run.exitCode, 0u) << run.output;
    EXPECT_NE(run.output.find("terrain: height field generated in"), std::string::npos) << run.output;
    std::filesystem::path field;
    for (const auto& file : filesIn(cache))
        if (file.filename().string().rfind("terrain-", 0) == 0) field = file;
    ASSERT_FALSE(field.empty());
    EXPECT_EQ(readFloatChannelExr(field).image.width, 2048);

    run = runWithCache(cache);
    EXPECT_NE(run.output.find("terrain: height field loaded from"), std::string::npos) << run.output;
    EXPECT_EQ(run.output.find("terrain: generating"), std::string::npos) << run.output;

    const std::string garbage = "not an EXR file";
    writeFileBytes(field, std::span(reinterpret_cast<const std::uint8_t*>(garbage.data()), garbage.size()));
    run = runWithCache(cache);
    ASSERT_EQ(run.exitCode, 0u) << run.output;
    EXPECT_NE(run.output.find(field.filename().string()), std::string::npos) << run.output;
    EXPECT_NE(run.output.find("generating the height field again"), std::string::npos) << run.output;
    EXPECT_EQ(readFloatChannelExr(field).image.width, 2048);  // cached again
    std::filesystem::remove_all(folder);
}

// The three models at once (the three-way view): each caches and exports its own tables, and a
// later run loads all three.
TEST(TableCache, EveryModelCachesAndExportsItsTables) {
    const auto folder = std::filesystem::temp_directory_path() / "firmament-table-cache-three";
    std::filesystem::remove_all(folder);
    const auto cache = folder / "cache", exported = folder / "exported";
    ProcessResult run = runWithCache(cache, {L"--set", L"atmosphere.comparison=Three-way", L"--export-luts", exported.wstring()});
    ASSERT_EQ(run.exitCode, 0u) << run.output;
    // Yusov's five, Bruneton's three, Hillaire's three, the terrain's height field, the clouds' optical depth.
    EXPECT_EQ(filesIn(cache).size(), 13u);
    for (const char* name : {"bruneton-transmittance.exr", "bruneton-irradiance.exr", "bruneton-inscatter.exr", "multiple-scattering.exr",
                             "hillaire-transmittance.exr", "hillaire-multiple-scattering.exr", "hillaire-irradiance.exr"})
        EXPECT_TRUE(std::filesystem::exists(exported / name)) << name;
    const ExrFile inscatter = readExr(exported / "bruneton-inscatter.exr");
    EXPECT_EQ(inscatter.image.width, 8 * 4);    // mu_s x nu
    EXPECT_EQ(inscatter.image.height, 32 * 8);  // mu x radius layers
    EXPECT_EQ(std::get<std::string>(inscatter.attributes.at("firmament.lut.dimensions")), "8 x 32 x 8 x 4 (r, mu, mu_s, nu)");
    for (const char* name : {"firmament.lut.name", "firmament.lut.layout", "firmament.lut.parameterization", "firmament.lut.key",
                             "firmament.atmosphere.groundAlbedo", "firmament.atmosphere.mieScattering", "firmament.lut.scale"})
        EXPECT_TRUE(inscatter.attributes.count(name)) << name;
    const FloatExrFile transmittance = readFloatExr(exported / "bruneton-transmittance.exr");
    EXPECT_EQ(transmittance.image.width, 64);
    EXPECT_GT(transmittance.image.rgba[(transmittance.image.width - 1) * 4], 0.5f);  // looking up from the ground: mostly clear
    // Hillaire's at Small: transmittance 64 x 16 (the zenith in the first column), the multiple
    // scattering 16 x 16, the sky irradiance 64 x 16, each describing itself.
    const FloatExrFile hillaire = readFloatExr(exported / "hillaire-transmittance.exr");
    EXPECT_EQ(hillaire.image.width, 64);
    EXPECT_EQ(hillaire.image.height, 16);
    EXPECT_GT(hillaire.image.rgba[0], 0.5f);  // straight up from the ground
    EXPECT_EQ(std::get<std::string>(hillaire.attributes.at("firmament.lut.model")), "Hillaire 2020");
    EXPECT_EQ(readFloatExr(exported / "hillaire-multiple-scattering.exr").image.width, 16);
    const FloatExrFile irradiance = readFloatExr(exported / "hillaire-irradiance.exr");
    EXPECT_EQ(irradiance.image.width, 64);
    for (const char* name : {"firmament.lut.name", "firmament.lut.layout", "firmament.lut.parameterization", "firmament.lut.key",
                             "firmament.lut.sampling", "firmament.atmosphere.mieScattering"})
        EXPECT_TRUE(irradiance.attributes.count(name)) << name;

    run = runWithCache(cache, {L"--set", L"atmosphere.comparison=Three-way"});
    ASSERT_EQ(run.exitCode, 0u) << run.output;
    EXPECT_EQ(run.output.find("pre-computing"), std::string::npos) << run.output;
    // Each model's log line: "<name>: tables <key> loaded from the cache in <folder>".
    for (const char* model : {"atmosphere: tables", "atmosphere (Bruneton 2008): tables", "atmosphere (Hillaire 2020): tables"}) {
        const size_t at = run.output.find(model);
        ASSERT_NE(at, std::string::npos) << model << "\n" << run.output;
        const std::string line = run.output.substr(at, run.output.find('\n', at) - at);
        EXPECT_NE(line.find("loaded from the cache"), std::string::npos) << line;
    }
    std::filesystem::remove_all(folder);
}

}  // namespace
}  // namespace firmament::test
