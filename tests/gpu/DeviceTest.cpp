// The WARP device: it exists, and reports its adapter and a feature level of at least 11_0.
#include "WarpDevice.h"
#include "core/Error.h"

namespace firmament::test {
namespace {

TEST_F(WarpDevice, ReportsAdapterAndFeatureLevel) {
    std::printf("adapter: %s\n", gpu->describe().c_str());
    RecordProperty("adapter", gpu->describe());
    EXPECT_FALSE(gpu->adapterName().empty());
    EXPECT_GE(gpu->featureLevel(), D3D_FEATURE_LEVEL_11_0);
    EXPECT_NE(featureLevelName(gpu->featureLevel()), "below 11_0");
}

TEST(Device, AnAdapterIndexThatDoesNotExistIsAClearError) {
    try {
        Device device(DeviceOptions{DriverType::Hardware, 63u, false});
        FAIL() << "adapter 63 should not exist";
    } catch (const Error& e) {
        EXPECT_NE(std::string(e.what()).find("no such adapter"), std::string::npos) << e.what();
    }
}

}  // namespace
}  // namespace firmament::test
