// Trilinear filtering with implicit derivatives: the level of detail a pixel shader's Sample
// picks, against the formula the Direct3D 11 specification gives (section 7.18.11): for
// isotropic filtering, lod = log2(max(|d(uv)/dx|, |d(uv)/dy|) * size), and the two nearest mips
// are blended by its fraction. Each mip of the probed texture holds its own index, so the
// value read is the level chosen. The terrain's far slopes (docs/terrain.md) depend on this.
#include "WarpDevice.h"
#include "gpu/CommonStates.h"
#include "gpu/ConstantBuffer.h"
#include "gpu/Readback.h"
#include "gpu/Texture.h"

#include <glm/glm.hpp>

#include <cmath>
#include <vector>

namespace firmament::test {
namespace {

constexpr int kTextureSide = 256;  // 9 mips
constexpr int kTarget = 64;        // 8 bands of 8 rows
constexpr int kBands = kTarget / 8;

struct ProbeConstants {
    glm::vec4 lodStep;
    glm::vec4 offset;
};

class MipSelection : public WarpDevice {
protected:
    // The mean level read in each band for texel steps of 2^(band * stepX) along x and
    // 2^(band * stepY) along y, `tiles` whole tiles from the origin.
    std::vector<double> levelsPerBand(DXGI_FORMAT format, float stepX, float stepY, float tiles) {
        const int mips = static_cast<int>(std::log2(kTextureSide)) + 1;
        D3D11_TEXTURE2D_DESC desc{};
        desc.Width = desc.Height = kTextureSide;
        desc.MipLevels = static_cast<UINT>(mips);
        desc.ArraySize = 1;
        desc.Format = format;
        desc.SampleDesc.Count = 1;
        desc.Usage = D3D11_USAGE_IMMUTABLE;
        desc.BindFlags = D3D11_BIND_SHADER_RESOURCE;
        const size_t channels = format == DXGI_FORMAT_R32G32_FLOAT ? 2 : 1;
        std::vector<std::vector<float>> texels(static_cast<size_t>(mips));
        std::vector<D3D11_SUBRESOURCE_DATA> data(static_cast<size_t>(mips));
        for (int m = 0; m < mips; ++m) {
            const int side = kTextureSide >> m;
            texels[static_cast<size_t>(m)].assign(static_cast<size_t>(side * side) * channels, static_cast<float>(m));
            data[static_cast<size_t>(m)] = {texels[static_cast<size_t>(m)].data(), static_cast<UINT>(side * channels * sizeof(float)), 0};
        }
        ComPtr<ID3D11Texture2D> texture;
        ComPtr<ID3D11ShaderResourceView> srv;
        EXPECT_HRESULT_SUCCEEDED(device()->CreateTexture2D(&desc, data.data(), &texture));
        EXPECT_HRESULT_SUCCEEDED(device()->CreateShaderResourceView(texture.Get(), nullptr, &srv));

        const Texture2D target = createColorTexture(device(), kTarget, kTarget, DXGI_FORMAT_R32G32B32A32_FLOAT, D3D11_BIND_RENDER_TARGET);
        ConstantBuffer<ProbeConstants> constants(device());
        constants.update(context(), {glm::vec4(stepX, stepY, static_cast<float>(kTextureSide), 0.0f), glm::vec4(tiles, tiles, 0.0f, 0.0f)});
        const auto sampler = states::linearWrap(device());
        const D3D11_VIEWPORT viewport{0, 0, kTarget, kTarget, 0, 1};
        ID3D11Buffer* buffer = constants.get();
        context()->OMSetRenderTargets(1, target.rtv.GetAddressOf(), nullptr);
        context()->RSSetViewports(1, &viewport);
        context()->IASetPrimitiveTopology(D3D11_PRIMITIVE_TOPOLOGY_TRIANGLELIST);
        context()->VSSetShader(testShaderLibrary->vertexShader({"draw/mip_selection.hlsl", "vs_main", "vs_5_0", {}}), nullptr, 0);
        context()->PSSetShader(testShaderLibrary->pixelShader({"draw/mip_selection.hlsl", "ps_main", "ps_5_0", {}}), nullptr, 0);
        context()->PSSetConstantBuffers(0, 1, &buffer);
        context()->PSSetShaderResources(0, 1, srv.GetAddressOf());
        context()->PSSetSamplers(0, 1, sampler.GetAddressOf());
        context()->Draw(3, 0);
        ID3D11ShaderResourceView* none = nullptr;
        context()->PSSetShaderResources(0, 1, &none);

        const auto pixels = asVector<float>(readTexture2D(device(), context(), target.texture.Get()).bytes);
        std::vector<double> levels(kBands, 0.0);
        for (int y = 0; y < kTarget; ++y)
            for (int x = 0; x < kTarget; ++x) levels[static_cast<size_t>(y / 8)] += pixels[(static_cast<size_t>(y) * kTarget + x) * 4];
        for (double& level : levels) level /= 8.0 * kTarget;
        return levels;
    }
};

// The specification's level for band b: log2 of the longer step, clamped to the mip chain.
double expectedLevel(int band, float stepX, float stepY) {
    const double lod = band * std::max(stepX, stepY);
    return std::clamp(lod, 0.0, std::log2(kTextureSide));
}

void expectLevels(const std::vector<double>& levels, float stepX, float stepY, const char* what) {
    // Implementations may approximate log2 and the fraction's blend: a tenth of a level.
    for (int b = 0; b < kBands; ++b)
        EXPECT_NEAR(levels[static_cast<size_t>(b)], expectedLevel(b, stepX, stepY), 0.1) << what << ", band " << b;
}

TEST_F(MipSelection, WholeLevelsForSquareFootprints) {
    expectLevels(levelsPerBand(DXGI_FORMAT_R32G32_FLOAT, 1.0f, 1.0f, 0.0f), 1.0f, 1.0f, "R32G32_FLOAT");
    expectLevels(levelsPerBand(DXGI_FORMAT_R32_FLOAT, 1.0f, 1.0f, 0.0f), 1.0f, 1.0f, "R32_FLOAT");
}

TEST_F(MipSelection, FractionalLevelsAreBlended) {
    expectLevels(levelsPerBand(DXGI_FORMAT_R32G32_FLOAT, 0.5f, 0.5f, 0.0f), 0.5f, 0.5f, "half-level steps");
}

TEST_F(MipSelection, TheLongerAxisDecidesForStretchedFootprints) {
    expectLevels(levelsPerBand(DXGI_FORMAT_R32G32_FLOAT, 1.0f, 0.0f, 0.0f), 1.0f, 0.0f, "stretched along x");
    expectLevels(levelsPerBand(DXGI_FORMAT_R32G32_FLOAT, 0.0f, 1.0f, 0.0f), 0.0f, 1.0f, "stretched along y");
}

TEST_F(MipSelection, FarFromTheOriginOfAWrappedTexture) {
    // The terrain's coordinates at 400 km up reach tens of tiles.
    expectLevels(levelsPerBand(DXGI_FORMAT_R32G32_FLOAT, 1.0f, 1.0f, 40.0f), 1.0f, 1.0f, "40 tiles out");
}

}  // namespace
}  // namespace firmament::test
