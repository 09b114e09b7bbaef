// The HDR pipeline on the WARP device against the CPU reference (src/postfx/ToneMappingCurves):
// every operator's output on a synthetic HDR ramp, before quantisation (a float target);
// monotonic ramps; zero, negative and huge input; the log-average luminance of the mip chain;
// light adaptation over time at two frame rates.
#include "WarpDevice.h"
#include "gpu/Readback.h"
#include "gpu/Texture.h"
#include "postfx/SceneLuminance.h"
#include "postfx/ToneMappingCurves.h"
#include "postfx/ToneMappingPass.h"

#include <Imath/half.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <string>

namespace firmament::test {
namespace {

// Largest allowed difference from the CPU reference, in display-encoded units, before the
// 8-bit quantisation: a quarter of one 8-bit step.
constexpr double kDisplayTolerance = 0.25 / 255.0;

// An RGBA16F image on the CPU, with the values the GPU sees (rounded to half).
struct HdrImage {
    int width = 0, height = 0;
    std::vector<glm::dvec3> pixels;

    HdrImage(int w, int h) : width(w), height(h), pixels(static_cast<size_t>(w) * h) {}
    void set(int x, int y, glm::dvec3 radiance) {
        for (int c = 0; c < 3; ++c) radiance[c] = static_cast<float>(Imath::half(static_cast<float>(radiance[c])));
        pixels[static_cast<size_t>(y) * width + x] = radiance;
    }
    glm::dvec3 at(int x, int y) const { return pixels[static_cast<size_t>(y) * width + x]; }
    Texture2D upload(ID3D11Device* device, ID3D11DeviceContext* context) const {
        std::vector<std::uint16_t> bits;
        for (const glm::dvec3& p : pixels)
            for (const double v : {p.r, p.g, p.b, 1.0}) bits.push_back(Imath::half(static_cast<float>(v)).bits());
        Texture2D t = createColorTexture(device, width, height, DXGI_FORMAT_R16G16B16A16_FLOAT, D3D11_BIND_SHADER_RESOURCE);
        context->UpdateSubresource(t.texture.Get(), 0, nullptr, bits.data(), static_cast<UINT>(width * 8), 0);
        return t;
    }
};

// Rows: 0 a grey ramp, 1 a warm colour ramp, 2 a saturated blue ramp, each from 1e-3 to 1e4
// (logarithmic); 3 special values: black, negative, the half maximum, single channels. The
// colour ramps keep their hue exactly in half precision: channel ratios are powers of two and
// every value stays above the half-float subnormals (6.1e-5).
constexpr int kRampWidth = 256;
HdrImage syntheticRamps() {
    HdrImage image(kRampWidth, 4);
    for (int x = 0; x < kRampWidth; ++x) {
        const double L = static_cast<float>(Imath::half(static_cast<float>(std::pow(10.0, -3.0 + 7.0 * x / (kRampWidth - 1)))));
        image.set(x, 0, glm::dvec3(L));
        image.set(x, 1, glm::dvec3(L, L / 2.0, L / 4.0));
        image.set(x, 2, glm::dvec3(L / 16.0, L / 8.0, L));
    }
    const glm::dvec3 special[] = {glm::dvec3(0.0), glm::dvec3(-1.0), glm::dvec3(-65504.0), glm::dvec3(65504.0),
                                  glm::dvec3(65504.0, 0.0, 0.0), glm::dvec3(0.0, 1e-6, 0.0), glm::dvec3(-3.0, 2.0, 0.5),
                                  glm::dvec3(1e-7, 0.0, 0.0)};
    for (int x = 0; x < kRampWidth; ++x) image.set(x, 3, special[x % std::size(special)]);
    return image;
}

struct FloatImage {
    int width = 0, height = 0;
    std::vector<float> rgba;
    glm::dvec3 at(int x, int y) const {
        const float* p = &rgba[(static_cast<size_t>(y) * width + x) * 4];
        return {p[0], p[1], p[2]};
    }
};

class ToneMappingGpu : public WarpDevice {
protected:
    FloatImage toneMap(const HdrImage& image, const ToneMappingSettings& settings, ID3D11ShaderResourceView* adapted = nullptr) {
        const Texture2D hdr = image.upload(device(), context());
        const Texture2D output = createColorTexture(device(), image.width, image.height, DXGI_FORMAT_R32G32B32A32_FLOAT,
                                                    D3D11_BIND_RENDER_TARGET);
        ToneMappingPass pass(device());
        pass.render(context(), *productShaderLibrary, settings, hdr.srv.Get(), adapted, output.rtv.Get(), image.width, image.height);
        const ReadbackImage read = readTexture2D(device(), context(), output.texture.Get());
        return {read.width, read.height, asVector<float>(read.bytes)};
    }

    float readScalar(ID3D11Texture2D* texture) { return asVector<float>(readTexture2D(device(), context(), texture).bytes).at(0); }
};

struct OperatorCase {
    ToneMapOperator op;
    float whitePoint;
    float saturation;
    float exposureEv;
};

class EveryOperator : public ToneMappingGpu, public ::testing::WithParamInterface<OperatorCase> {};

TEST_P(EveryOperator, MatchesItsFormulaMonotonicallyAndWithoutNan) {
    const OperatorCase c = GetParam();
    ToneMappingSettings settings;
    settings.op = c.op;
    settings.autoExposure = false;
    settings.exposureEv = c.exposureEv;
    settings.whitePoint = c.whitePoint;
    settings.luminanceSaturation = c.saturation;
    const tonemap::Parameters reference{c.op, std::exp2(static_cast<double>(c.exposureEv)), c.whitePoint, c.saturation};

    const HdrImage image = syntheticRamps();
    const FloatImage display = toneMap(image, settings);
    double worst = 0.0;
    for (int y = 0; y < image.height; ++y) {
        for (int x = 0; x < image.width; ++x) {
            const glm::dvec3 expected = tonemap::toDisplay(image.at(x, y), reference);
            const glm::dvec3 got = display.at(x, y);
            for (int ch = 0; ch < 3; ++ch) {
                ASSERT_TRUE(std::isfinite(got[ch])) << "row " << y << " column " << x;
                ASSERT_GE(got[ch], 0.0);
                ASSERT_LE(got[ch], 1.0);
                worst = std::max(worst, std::abs(got[ch] - expected[ch]));
                ASSERT_NEAR(got[ch], expected[ch], kDisplayTolerance)
                    << "row " << y << " column " << x << " channel " << ch << " radiance " << image.at(x, y)[ch];
            }
            if (y < 3 && x > 0) {
                for (int ch = 0; ch < 3; ++ch)
                    ASSERT_GE(got[ch], display.at(x - 1, y)[ch] - 1e-6) << "not monotonic: row " << y << " column " << x;
            }
        }
    }
    std::printf("%s (white %.2f, saturation %.2f, %+.1f EV): largest difference %.2e (%.3f / 255)\n",
                std::string(kToneMapOperatorNames[static_cast<size_t>(c.op)]).c_str(), c.whitePoint, c.saturation, c.exposureEv,
                worst, worst * 255.0);
}

INSTANTIATE_TEST_SUITE_P(
    SevenOperators, EveryOperator,
    ::testing::Values(OperatorCase{ToneMapOperator::Exp, 3.0f, 1.0f, 0.0f}, OperatorCase{ToneMapOperator::Exp, 3.0f, 0.6f, 2.0f},
                      OperatorCase{ToneMapOperator::Reinhard, 3.0f, 1.0f, 0.0f},
                      OperatorCase{ToneMapOperator::Reinhard, 3.0f, 1.7f, -3.0f},
                      OperatorCase{ToneMapOperator::ReinhardModified, 3.0f, 1.0f, 0.0f},
                      OperatorCase{ToneMapOperator::ReinhardModified, 0.5f, 0.8f, 1.0f},
                      OperatorCase{ToneMapOperator::Uncharted2, 3.0f, 1.0f, 0.0f},
                      OperatorCase{ToneMapOperator::Uncharted2, 11.2f, 1.0f, -1.0f},
                      OperatorCase{ToneMapOperator::FilmicAlu, 3.0f, 1.0f, 0.0f},
                      OperatorCase{ToneMapOperator::FilmicAlu, 3.0f, 1.0f, 3.0f},
                      OperatorCase{ToneMapOperator::Logarithmic, 3.0f, 1.0f, 0.0f},
                      OperatorCase{ToneMapOperator::Logarithmic, 10.0f, 0.5f, 2.0f},
                      OperatorCase{ToneMapOperator::AdaptiveLogarithmic, 3.0f, 1.0f, 0.0f},
                      OperatorCase{ToneMapOperator::AdaptiveLogarithmic, 0.2f, 1.3f, -2.0f}),
    [](const ::testing::TestParamInfo<OperatorCase>& param) {
        std::string name(kToneMapOperatorNames[static_cast<size_t>(param.param.op)]);
        std::erase(name, ' ');
        return name + "_" + std::to_string(param.index);
    });

// A wide-range test frame: bright and dark bands, a gradient and black pixels.
HdrImage luminanceTestFrame(int width, int height) {
    HdrImage image(width, height);
    for (int y = 0; y < height; ++y)
        for (int x = 0; x < width; ++x) {
            const double u = static_cast<double>(x) / width, v = static_cast<double>(y) / height;
            double L = std::pow(10.0, -2.0 + 4.0 * u) * (1.0 + 0.5 * std::sin(20.0 * v));
            if ((x / 16 + y / 16) % 5 == 0) L = 0.0;  // black squares: the delta inside the logarithm counts
            image.set(x, y, glm::dvec3(1.2 * L, L, 0.7 * L));
        }
    return image;
}

double cpuMeanLogLuminance(const HdrImage& image) { return tonemap::meanLogLuminance(image.pixels); }

// The metering of Yusov's sample: the log-average of every pixel.
ToneMappingSettings logAverage() {
    ToneMappingSettings settings;
    settings.metering = Metering::LogAverage;
    return settings;
}

// A 256 x 256 frame is sampled pixel for pixel: the mip chain's last level is the mean of
// ln(delta + L) over every pixel, up to float rounding. Other sizes are sampled on a 4 x 4
// grid per texel of the 64 x 64 target: close to the mean, within the stated 0.02 (2% of the
// average luminance).
TEST_F(ToneMappingGpu, LogAverageLuminanceMatchesTheCpu) {
    struct Size { int width, height; double tolerance; };
    for (const Size size : {Size{256, 256, 2e-5}, Size{640, 360, 0.02}, Size{300, 170, 0.02}}) {
        const HdrImage image = luminanceTestFrame(size.width, size.height);
        const Texture2D hdr = image.upload(device(), context());
        SceneLuminance luminance(device());
        luminance.measure(context(), *productShaderLibrary, hdr.srv.Get(), size.width, size.height, logAverage());
        luminance.adapt(context(), *productShaderLibrary, 0.1f);  // the first adapt() takes the measured value
        const double measured = readScalar(luminance.adaptedLogLuminanceTexture());
        const double reference = cpuMeanLogLuminance(image);
        std::printf("%dx%d: ln L_avg GPU %.6f, CPU %.6f (difference %.2e)\n", size.width, size.height, measured, reference,
                    measured - reference);
        EXPECT_NEAR(measured, reference, size.tolerance) << size.width << "x" << size.height;
    }
}

// Histogram metering (postfx/luminance_histogram.hlsl) against its CPU twin on the same 64 x 64
// log-luminance texels (within 0.005: the shader sums in fixed point of 1/256), for the test
// frame and for a frame whose upper 40% is black, like space above the Earth: there the black is
// left out, so the metered luminance is the lit part's (within 1%), where the log-average is
// dragged down by orders of magnitude.
TEST_F(ToneMappingGpu, HistogramMeteringLeavesBlackOutAndMatchesItsCpuTwin) {
    HdrImage earth(320, 180);
    for (int y = 0; y < 180; ++y)
        for (int x = 0; x < 320; ++x) earth.set(x, y, y < 72 ? glm::dvec3(0.0) : glm::dvec3(5.0 * (1.0 + 0.2 * std::sin(0.3 * x))));
    struct Case {
        const char* name;
        const HdrImage* image;
    };
    const HdrImage ramps = luminanceTestFrame(640, 360);
    for (const Case c : {Case{"test frame", &ramps}, Case{"40% black", &earth}}) {
        const Texture2D hdr = c.image->upload(device(), context());
        SceneLuminance luminance(device());
        const ToneMappingSettings settings;  // Histogram, 10% to 98%
        ASSERT_EQ(settings.metering, Metering::Histogram);
        luminance.measure(context(), *productShaderLibrary, hdr.srv.Get(), c.image->width, c.image->height, settings);
        const double metered = readScalar(luminance.measuredTexture());
        for (const auto& [what, error] : productShaderLibrary->errors()) ADD_FAILURE() << what << ": " << error;
        const ReadbackImage texels = readTexture2D(device(), context(), luminance.logLuminanceTexture());
        ASSERT_EQ(texels.width * texels.height, 64 * 64);
        const std::vector<float> values = asVector<float>(texels.bytes);
        const double twin = tonemap::histogramMeanLogLuminance(values, settings.histogramLow, settings.histogramHigh);
        const double everyPixel = cpuMeanLogLuminance(*c.image);
        std::printf("%s: metered ln L GPU %.5f, CPU twin %.5f; log-average of every pixel %.5f\n", c.name, metered, twin, everyPixel);
        EXPECT_NEAR(metered, twin, 0.005) << c.name;
        if (c.image == &earth) {
            EXPECT_NEAR(metered, std::log(5.0), 0.01);
            EXPECT_LT(everyPixel, metered - 3.0);
        }
    }
}

// Auto exposure end to end: a uniform frame of luminance L maps to the operator's value at
// the middle grey (Ls = key / L_avg * L = key when L_avg = L, up to the delta).
TEST_F(ToneMappingGpu, AutoExposureMapsTheAverageToMiddleGray) {
    HdrImage image(64, 64);
    const glm::dvec3 radiance(30.0, 25.0, 20.0);
    for (int y = 0; y < 64; ++y)
        for (int x = 0; x < 64; ++x) image.set(x, y, radiance);
    const Texture2D hdr = image.upload(device(), context());
    SceneLuminance luminance(device());
    luminance.measure(context(), *productShaderLibrary, hdr.srv.Get(), 64, 64, logAverage());
    luminance.adapt(context(), *productShaderLibrary, 1.0f);

    ToneMappingSettings settings;
    settings.op = ToneMapOperator::Reinhard;
    settings.middleGray = 0.25f;
    const FloatImage display = toneMap(image, settings, luminance.adaptedLogLuminance());
    const double L = tonemap::relativeLuminance(image.at(0, 0));
    const double averageL = std::exp(std::log(tonemap::kLogLuminanceDelta + L));
    const double exposure = tonemap::autoExposure(averageL, 0.25, 1.0);
    EXPECT_NEAR(exposure * L, 0.25, 1e-5);
    const glm::dvec3 expected = tonemap::toDisplay(image.at(0, 0), {ToneMapOperator::Reinhard, exposure, 3.0, 1.0});
    for (int ch = 0; ch < 3; ++ch) EXPECT_NEAR(display.at(17, 40)[ch], expected[ch], kDisplayTolerance);
}

// After the scene's luminance steps from L_a to L_b, the adapted log luminance follows
// ln L_b + (ln L_a - ln L_b) exp(-t / tau), the same at 30 and at 144 frames a second.
TEST_F(ToneMappingGpu, LightAdaptationFollowsItsTimeConstantAtAnyFrameRate) {
    auto uniform = [](double L) {
        HdrImage image(64, 64);
        for (int y = 0; y < 64; ++y)
            for (int x = 0; x < 64; ++x) image.set(x, y, glm::dvec3(L));
        return image;
    };
    const HdrImage dark = uniform(0.05), bright = uniform(40.0);
    const Texture2D darkFrame = dark.upload(device(), context()), brightFrame = bright.upload(device(), context());
    const double lnA = std::log(tonemap::kLogLuminanceDelta + tonemap::relativeLuminance(dark.at(0, 0)));
    const double lnB = std::log(tonemap::kLogLuminanceDelta + tonemap::relativeLuminance(bright.at(0, 0)));
    const double tau = 0.4;
    for (const int framesPerSecond : {30, 144}) {
        SceneLuminance luminance(device());
        luminance.measure(context(), *productShaderLibrary, darkFrame.srv.Get(), 64, 64, logAverage());
        luminance.adapt(context(), *productShaderLibrary, 0.5f);  // first frame: adapted to the dark scene
        const double dt = 1.0 / framesPerSecond;
        const float weight = static_cast<float>(tonemap::adaptationWeight(dt, tau));
        for (int frame = 1; frame <= framesPerSecond; ++frame) {  // one second in the bright scene
            luminance.measure(context(), *productShaderLibrary, brightFrame.srv.Get(), 64, 64, logAverage());
            luminance.adapt(context(), *productShaderLibrary, weight);
            const double t = frame * dt;
            if (frame % (framesPerSecond / 10) != 0) continue;  // check every 0.1 s
            const double expected = lnB + (lnA - lnB) * std::exp(-t / tau);
            EXPECT_NEAR(readScalar(luminance.adaptedLogLuminanceTexture()), expected, 2e-4)
                << framesPerSecond << " fps at t = " << t << " s";
        }
    }
}

}  // namespace
}  // namespace firmament::test
