// The structures shared by C++ and HLSL have one layout: a compute shader copies the
// FrameConstants buffer as HLSL sees it, and every float must be where C++ put it.
#include "WarpDevice.h"
#include "gpu/ConstantBuffer.h"
#include "gpu/SharedStructures.h"

namespace firmament::test {
namespace {

TEST_F(WarpDevice, FrameConstantsHaveTheSameLayoutInHlslAndCpp) {
    gpu::FrameConstants constants{};
    float* values = reinterpret_cast<float*>(&constants);
    for (size_t i = 0; i < sizeof(constants) / sizeof(float); ++i) values[i] = static_cast<float>(i) + 0.5f;  // all distinct
    ConstantBuffer<gpu::FrameConstants> buffer(device());
    buffer.update(context(), constants);

    auto output = structuredBuffer(std::vector<glm::vec4>(18, glm::vec4(-1.0f)), true);
    ComPtr<ID3D11UnorderedAccessView> uav;
    ASSERT_HRESULT_SUCCEEDED(device()->CreateUnorderedAccessView(output.Get(), nullptr, &uav));
    context()->CSSetShader(testShaderLibrary->computeShader({"constants/echo_frame_constants.hlsl", "main", "cs_5_0", {}}), nullptr, 0);
    context()->CSSetConstantBuffers(0, 1, buffer.address());
    context()->CSSetUnorderedAccessViews(0, 1, uav.GetAddressOf(), nullptr);
    context()->Dispatch(1, 1, 1);
    const auto echoed = asVector<glm::vec4>(readBuffer(device(), context(), output.Get()));

    // HLSL's M[row] is row `row` of the matrix; GLM stores columns: m[column][row].
    for (int row = 0; row < 4; ++row)
        for (int column = 0; column < 4; ++column) {
            EXPECT_EQ(echoed[row][column], constants.viewProjection[column][row]) << "viewProjection " << row << "," << column;
            EXPECT_EQ(echoed[4 + row][column], constants.inverseViewProjection[column][row]);
            EXPECT_EQ(echoed[8 + row][column], constants.clipToDirection[column][row]);
        }
    EXPECT_EQ(echoed[12], constants.cameraPosition);
    EXPECT_EQ(echoed[13], constants.directionToSun);
    EXPECT_EQ(echoed[14], constants.screen);
    EXPECT_EQ(echoed[15], constants.time);
    EXPECT_EQ(echoed[16], constants.sunIrradiance);
    EXPECT_EQ(echoed[17], constants.planet);
}

}  // namespace
}  // namespace firmament::test
