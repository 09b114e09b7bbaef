// The WARP device: it exists, and reports its adapter and a feature level of at least 11_0. The
// device the program is given counts the objects it makes that are alive, by kind, and DXGI and
// the interfaces beyond ID3D11Device are the driver's.
#include "WarpDevice.h"
#include "core/Error.h"
#include "gpu/CommonStates.h"

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

TEST_F(WarpDevice, CountsTheObjectsItMakesWhileTheyLive) {
    const LiveObjectCounts before = gpu->liveObjects();
    {
        D3D11_TEXTURE2D_DESC desc{};
        desc.Width = desc.Height = 4;
        desc.MipLevels = desc.ArraySize = 1;
        desc.Format = DXGI_FORMAT_R8G8B8A8_UNORM;
        desc.SampleDesc.Count = 1;
        desc.BindFlags = D3D11_BIND_SHADER_RESOURCE | D3D11_BIND_RENDER_TARGET;
        ComPtr<ID3D11Texture2D> texture;
        ASSERT_EQ(gpu->device()->CreateTexture2D(&desc, nullptr, &texture), S_OK);
        ComPtr<ID3D11ShaderResourceView> srv;
        ComPtr<ID3D11RenderTargetView> rtv;
        ASSERT_EQ(gpu->device()->CreateShaderResourceView(texture.Get(), nullptr, &srv), S_OK);
        ASSERT_EQ(gpu->device()->CreateRenderTargetView(texture.Get(), nullptr, &rtv), S_OK);
        // The runtime hands out an identical state object again: it is one object, counted once.
        ComPtr<ID3D11SamplerState> a = states::linearClamp(gpu->device());
        ComPtr<ID3D11SamplerState> b = states::linearClamp(gpu->device());

        const LiveObjectCounts during = gpu->liveObjects();
        EXPECT_EQ(during[GpuObjectKind::Texture] - before[GpuObjectKind::Texture], 1);
        EXPECT_EQ(during[GpuObjectKind::View] - before[GpuObjectKind::View], 2);
        const long samplers = during[GpuObjectKind::State] - before[GpuObjectKind::State];
        EXPECT_EQ(samplers, a.Get() == b.Get() ? 1 : 2);
        EXPECT_EQ(during.total() - before.total(), 3 + samplers) << during.describe();
        // A view keeps its texture alive: with the texture's own reference gone, both still count.
        texture.Reset();
        EXPECT_EQ(gpu->liveObjects()[GpuObjectKind::Texture] - before[GpuObjectKind::Texture], 1);
    }
    const LiveObjectCounts after = gpu->liveObjects();
    EXPECT_EQ(after.total(), before.total()) << "before " << before.describe() << ", after " << after.describe();
}

TEST_F(WarpDevice, DxgiAndNewerInterfacesAreTheDriversOwn) {
    ComPtr<IDXGIDevice> dxgi;
    ASSERT_EQ(gpu->device()->QueryInterface(IID_PPV_ARGS(&dxgi)), S_OK);
    ComPtr<ID3D11Device> back;
    ASSERT_EQ(dxgi.As(&back), S_OK);
    EXPECT_EQ(back.Get(), gpu->driverDevice());
    ComPtr<ID3D11Device> same;
    ASSERT_EQ(gpu->device()->QueryInterface(IID_PPV_ARGS(&same)), S_OK);
    EXPECT_EQ(same.Get(), gpu->device());
    EXPECT_EQ(gpu->device()->GetFeatureLevel(), gpu->driverDevice()->GetFeatureLevel());
}

TEST(LiveObjectCounts, DescribeNamesTheKindsThatHaveObjects) {
    LiveObjectCounts c;
    EXPECT_EQ(c.describe(), "0");
    c.byKind[static_cast<int>(GpuObjectKind::Texture)] = 3;
    c.byKind[static_cast<int>(GpuObjectKind::Shader)] = 2;
    EXPECT_EQ(c.total(), 5);
    EXPECT_EQ(c.describe(), "5 (textures 3, shaders 2)");
}

}  // namespace
}  // namespace firmament::test
