// The program's display-encode pass against the sRGB transfer function on the CPU:
// every HDR value, scaled by 2^EV, clamped to [0,1], encoded within half a step of 8 bits.
#include "WarpDevice.h"
#include "gpu/Readback.h"
#include "gpu/Texture.h"
#include "postfx/DisplayEncodePass.h"

#include <Imath/half.h>

#include <algorithm>
#include <cmath>

namespace firmament::test {
namespace {

// IEC 61966-2-1.
double srgbEncode(double linear) {
    linear = std::clamp(linear, 0.0, 1.0);
    return linear <= 0.0031308 ? 12.92 * linear : 1.055 * std::pow(linear, 1.0 / 2.4) - 0.055;
}

class DisplayEncode : public WarpDevice, public ::testing::WithParamInterface<float> {};

TEST_P(DisplayEncode, MatchesTheSrgbCurveAfterExposure) {
    ToneMappingSettings settings;
    settings.exposureEv = GetParam();
    const double scale = std::exp2(static_cast<double>(settings.exposureEv));
    constexpr int kWidth = 256, kHeight = 2;
    // Row 0: a ramp over [-0.5, 1.5] (negative and over-range values clamp).
    // Row 1: a logarithmic ramp from 1e-5 to 1 (the linear toe of the curve included).
    std::vector<float> linear(kWidth * kHeight * 4);
    for (int x = 0; x < kWidth; ++x) {
        const float ramp = -0.5f + 2.0f * static_cast<float>(x) / (kWidth - 1);
        const float logRamp = std::pow(10.0f, -5.0f + 5.0f * static_cast<float>(x) / (kWidth - 1));
        const float rows[2][4] = {{ramp, ramp * 0.5f, 1.0f - ramp, 1.0f}, {logRamp, logRamp, logRamp * 0.25f, 1.0f}};
        for (int y = 0; y < kHeight; ++y)
            for (int c = 0; c < 4; ++c) linear[(y * kWidth + x) * 4 + c] = Imath::half(rows[y][c]);  // what the GPU sees
    }
    std::vector<std::uint16_t> halfBits(linear.size());
    for (size_t i = 0; i < linear.size(); ++i) halfBits[i] = Imath::half(linear[i]).bits();

    const Texture2D hdr = createColorTexture(device(), kWidth, kHeight, DXGI_FORMAT_R16G16B16A16_FLOAT, D3D11_BIND_SHADER_RESOURCE);
    context()->UpdateSubresource(hdr.texture.Get(), 0, nullptr, halfBits.data(), kWidth * 8, 0);
    const Texture2D output = createColorTexture(device(), kWidth, kHeight, DXGI_FORMAT_R8G8B8A8_UNORM, D3D11_BIND_RENDER_TARGET);

    DisplayEncodePass pass(device());
    pass.render(context(), *productShaderLibrary, settings, hdr.srv.Get(), output.rtv.Get(), kWidth, kHeight);
    const ReadbackImage image = readTexture2D(device(), context(), output.texture.Get());

    double worst = 0.0;
    for (size_t i = 0; i < image.bytes.size(); ++i) {
        if (i % 4 == 3) continue;
        const double expected = 255.0 * srgbEncode(linear[i] * scale);
        worst = std::max(worst, std::abs(image.bytes[i] - expected));
        ASSERT_LE(std::abs(image.bytes[i] - expected), 0.6) << "texel " << i / 4 << " channel " << i % 4 << " linear "
                                                            << linear[i];
    }
    std::printf("EV %+.1f: largest difference from the sRGB curve: %.3f / 255\n", settings.exposureEv, worst);
}

INSTANTIATE_TEST_SUITE_P(ExposureValues, DisplayEncode, ::testing::Values(0.0f, -1.5f, 2.0f));

}  // namespace
}  // namespace firmament::test
