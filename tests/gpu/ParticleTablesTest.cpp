// The cloud particle's optical depth table (src/clouds/ParticleTables.h,
// shaders/clouds/precompute_optical_depth.hlsl) on the WARP device: texels against the CPU
// twin's march through the same noise for every density method, and the table through the
// cache's files and back.
#include "WarpDevice.h"
#include "clouds/OpticalDepthTable.h"
#include "clouds/ParticleTables.h"

#include <gtest/gtest.h>

#include <cmath>
#include <cstring>
#include <filesystem>
#include <random>

namespace firmament::test {
namespace {

// A small table: the same parameterization, a fraction of the work.
ParticleTableParameters smallTable(ParticleDensityMethod method) {
    ParticleTableParameters p;
    p.method = method;
    p.opticalDepth = {8, 16, 8, 16, 24};
    return p;
}

std::vector<float> readTable(ID3D11Device* device, ID3D11DeviceContext* context, const ParticleTablePrecomputation& tables) {
    const ReadbackVolume volume = readTexture3D(device, context, tables.tables().opticalDepth.texture.Get());
    std::vector<float> values(volume.bytes.size() / sizeof(float));
    std::memcpy(values.data(), volume.bytes.data(), volume.bytes.size());
    return values;
}

class ParticleTablesTest : public WarpDevice {};

TEST_F(ParticleTablesTest, OpticalDepthTexelsMatchACpuMarchThroughTheSameNoise) {
    for (ParticleDensityMethod method : {ParticleDensityMethod::RadialNoise, ParticleDensityMethod::ThresholdedNoise, ParticleDensityMethod::Pyroclastic}) {
        const ParticleTableParameters p = smallTable(method);
        ParticleTablePrecomputation tables(device(), p);
        tables.runAll(context(), *productShaderLibrary);
        const std::vector<float> table = readTable(device(), context(), tables);
        const OpticalDepthTableSize& n = p.opticalDepth;
        ASSERT_EQ(table.size(), static_cast<size_t>(n.width()) * n.height() * n.depth());
        std::mt19937 random(7);
        double worst = 0.0, sum = 0.0;
        int thresholdFlips = 0;
        for (int k = 0; k < 300; ++k) {
            const int x = static_cast<int>(random() % n.width()), y = static_cast<int>(random() % n.height()), z = static_cast<int>(random() % n.depth());
            const float cpu = meanChordDensity(opticalDepthRay(opticalDepthTexelCoordinates(n, x, y, z)), n.steps, method);
            const double difference = std::abs(table[(static_cast<size_t>(z) * n.height() + y) * n.width() + x] - cpu);
            // The 0-or-1 methods may flip one step where the noise sits within rounding of the threshold.
            if (method != ParticleDensityMethod::RadialNoise && std::abs(difference - 1.0 / n.steps) < 1e-4) {
                ++thresholdFlips;
                continue;
            }
            worst = std::max(worst, difference);
            sum += cpu;
        }
        EXPECT_LT(worst, 1e-4) << kParticleDensityMethodNames[static_cast<size_t>(method)];
        EXPECT_LE(thresholdFlips, 3);
        EXPECT_GT(sum / 300.0, 0.05) << "the table is not empty";
    }
}

TEST_F(ParticleTablesTest, TheTableSurvivesTheCacheFilesBitForBit) {
    const ParticleTableParameters p = smallTable(ParticleDensityMethod::RadialNoise);
    ParticleTablePrecomputation computed(device(), p);
    computed.runAll(context(), *productShaderLibrary);
    const std::filesystem::path folder = std::filesystem::temp_directory_path() / "firmament-particle-table-cache";
    std::filesystem::remove_all(folder);
    const std::string key = particleTableKey(p, *productShaderLibrary);
    writeTables(device(), context(), computed, key, folder, key + "-");
    ParticleTablePrecomputation loaded(device(), p);
    EXPECT_EQ(readTables(context(), loaded, key, folder, key + "-"), "");
    EXPECT_TRUE(loaded.done());
    EXPECT_EQ(readTable(device(), context(), loaded), readTable(device(), context(), computed));
    // A file made for another key is refused with the reason.
    std::filesystem::copy_file(folder / (key + "-cloud-optical-depth.exr"), folder / "0123456789abcdef-cloud-optical-depth.exr");
    ParticleTablePrecomputation other(device(), p);
    EXPECT_NE(readTables(context(), other, "0123456789abcdef", folder, "0123456789abcdef-").find("key differs"), std::string::npos);
    EXPECT_FALSE(other.done());
    std::filesystem::remove_all(folder);
    // Another method makes another key.
    EXPECT_NE(particleTableKey(smallTable(ParticleDensityMethod::Pyroclastic), *productShaderLibrary), key);
}

}  // namespace
}  // namespace firmament::test
