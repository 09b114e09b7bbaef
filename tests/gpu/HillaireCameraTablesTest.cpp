// Hillaire 2020's tables that follow the camera, made by the model's pass on the GPU, against
// the CPU reference atmosphere (src/reference/ReferenceAtmosphere):
//  - the sky-view table: each sampled texel's view, single scattering from the reference (exact
//    quadrature) plus the higher orders, T(x, y) sigma_s(y) Psi_ms(y) integrated along the view
//    in 64 steps with the reference's T and Psi_ms read from the model's multiple-scattering
//    table (which HillaireTables.MultipleScatteringMatchesItsCpuTwin holds to its CPU twin);
//  - the aerial-perspective volume: the transmittance from the camera to sampled froxels against
//    the reference's, and the light scattered on the way the same as the sky view's.
//  - the sky irradiance table Firmament adds: the same light integrated over the upper hemisphere
//    on a product grid of directions, against the pass's 256 spherical Fibonacci directions
//    (full tier).
// The model's march (shaders/atmosphere/hillaire/march.hlsli) takes 30 growing steps along a view
// and 2 equal steps per slice at the paper's defaults; the bounds are what those steps reach,
// measured here. With 30 equal steps the sky view failed: 9.7% of the brightest from the ground
// toward the sun, where the first step crossed the aerosols' layer at once.
#include "WarpDevice.h"
#include "atmosphere/hillaire/HillaireParameterization.h"
#include "atmosphere/hillaire/HillairePass.h"
#include "atmosphere/hillaire/HillairePrecomputation.h"
#include "core/Camera.h"
#include "gpu/ConstantBuffer.h"
#include "gpu/Readback.h"
#include "reference/ReferenceAtmosphere.h"

#include <glm/gtc/constants.hpp>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <cstring>
#include <string>
#include <vector>

namespace firmament::test {
namespace {

namespace hillaire = atmosphere::hillaire;

constexpr int kHigherOrderSteps = 64;

class HillaireCameraTables : public WarpDevice {
public:
    const AtmosphereParameters& physics() const { return parameters.physics; }
    glm::dvec3 radiance(glm::dvec3 start, glm::dvec3 view, glm::dvec3 sun) const { return expectedRadiance(start, view, sun); }

protected:
    void SetUp() override {
        WarpDevice::SetUp();
        tables = std::make_unique<HillairePrecomputation>(device(), parameters);
        tables->runAll(context(), *productShaderLibrary);
        psi = readTexture2D(device(), context(), tables->tables().multipleScattering.texture.Get());
        frameConstants = std::make_unique<ConstantBuffer<gpu::FrameConstants>>(device());
    }

    // The camera `altitude` metres above the origin, looking along yaw and pitch, the sun at
    // `sunElevation` degrees (azimuth 30 degrees); the pass makes both tables for it.
    void makeTables(double altitude, double sunElevation, float pitch = 0.0f) {
        camera.position = glm::vec3(0.0f, static_cast<float>(altitude), 0.0f);
        camera.yawDegrees = 10.0f;
        camera.pitchDegrees = pitch;
        camera.verticalFovDegrees = 60.0f;
        const double e = glm::radians(sunElevation), azimuth = glm::radians(30.0);
        sunDir = glm::dvec3(std::cos(e) * std::sin(azimuth), std::sin(e), std::cos(e) * std::cos(azimuth));
        glm::mat4 rotationOnly = camera.view();
        rotationOnly[3] = glm::vec4(0.0f, 0.0f, 0.0f, 1.0f);
        constants = {};
        constants.clipToDirection = glm::inverse(camera.projection(1.0f) * rotationOnly);
        constants.cameraPosition = glm::vec4(camera.position, camera.position.y);
        constants.directionToSun = glm::vec4(glm::vec3(sunDir), 0.0f);
        frameConstants->update(context(), constants);
        pass = std::make_unique<HillairePass>(device());
        pass->makeCameraTables(context(), *productShaderLibrary, *tables, frameConstants->get(), sampling);
    }

    // The model's light along a view from `start`, the sun along `sun`, per unit sun irradiance,
    // over the view's first `length` metres (all of it by default): the reference's single
    // scattering and the twin's higher orders.
    glm::dvec3 expectedRadiance(glm::dvec3 start, glm::dvec3 view, glm::dvec3 sun, double length = 1e300) const {
        const atmosphere::ReferenceAtmosphere& ref = reference;
        glm::dvec3 single = ref.singleScattering(start, view, sun);
        if (length < ref.rayLength(start, view)) {  // over [0, length): all of it less T(0, length) times what lies beyond
            const glm::dvec3 end = start + view * length;
            single -= glm::exp(-ref.opticalDepth(ref.netDensity(start, end))) * ref.singleScattering(end, view, sun);
        }
        const double dt = std::min(length, ref.rayLength(start, view)) / kHigherOrderSteps;
        glm::dvec3 higher(0.0);
        for (int i = 0; i < kHigherOrderSteps; ++i) {
            const glm::dvec3 y = start + view * ((i + 0.5) * dt);
            const double r = glm::length(y);
            const glm::dvec3 density = ref.density(r - parameters.physics.earthRadius);
            const glm::dvec3 scattering = parameters.physics.rayleighScattering * density.x + parameters.physics.mieScattering * density.y;
            higher += glm::exp(-ref.opticalDepth(ref.netDensity(start, y))) * scattering * psiAt(r, glm::dot(y, sun) / r) * dt;
        }
        return single + higher;
    }

    // Psi_ms from the model's table, bilinear between texel centres as the sampler reads it.
    glm::dvec3 psiAt(double r, double muS) const {
        const glm::dvec2 unit = hillaire::multipleScatteringUnit(parameters.physics, r, muS);
        const double x = unit.x * (psi.width - 1), y = unit.y * (psi.height - 1);
        const int x0 = std::min(static_cast<int>(x), psi.width - 2), y0 = std::min(static_cast<int>(y), psi.height - 2);
        const double fx = x - x0, fy = y - y0;
        const auto at = [&](int i, int j) { return texel(psi.bytes.data(), static_cast<size_t>(j) * psi.width + i); };
        return glm::mix(glm::mix(at(x0, y0), at(x0 + 1, y0), fx), glm::mix(at(x0, y0 + 1), at(x0 + 1, y0 + 1), fx), fy);
    }

public:
    static glm::dvec3 texel(const void* bytes, size_t index) {
        float rgba[4];
        std::memcpy(rgba, static_cast<const std::uint8_t*>(bytes) + index * sizeof(rgba), sizeof(rgba));
        return {rgba[0], rgba[1], rgba[2]};
    }

protected:
    HillaireParameters parameters;
    atmosphere::ReferenceAtmosphere reference{parameters.physics};
    HillaireFrameSampling sampling;  // the paper's
    std::unique_ptr<HillairePrecomputation> tables;
    ReadbackImage psi;
    std::unique_ptr<ConstantBuffer<gpu::FrameConstants>> frameConstants;
    std::unique_ptr<HillairePass> pass;
    gpu::FrameConstants constants{};
    Camera camera;
    glm::dvec3 sunDir{0.0, 1.0, 0.0};
};

struct Sample {
    glm::dvec3 got, expected;
    std::string where;
};

struct Errors {
    std::vector<double> values;
    void add(double e) { values.push_back(e); }
    double median() {
        std::sort(values.begin(), values.end());
        return values[values.size() / 2];
    }
    double largest() const { return *std::max_element(values.begin(), values.end()); }
};

// Sampled texels of the sky view (every 32nd column, rows all the way from the zenith to the
// nadir) from the ground, 1 km and 10 km, the sun high and low: each channel's error relative
// to the case's brightest expected channel.
// Measured: largest 0.70%, 0.21% and 0.04%; medians 0.01% or less.
TEST_F(HillaireCameraTables, SkyViewMatchesTheReference) {
    constexpr double kLargest = 0.015, kMedian = 0.002;
    struct Case {
        double altitude, sunElevation;
    };
    for (const Case c : {Case{2.0, 30.0}, Case{1000.0, 5.0}, Case{10000.0, 60.0}}) {
        makeTables(c.altitude, c.sunElevation);
        const ReadbackImage image = readTexture2D(device(), context(), pass->cameraTables().skyView.texture.Get());
        const AtmosphereParameters& p = parameters.physics;
        const double r = p.earthRadius + c.altitude;
        const glm::dvec3 start(0.0, r, 0.0);
        // The sun's horizontal part lies along +x in the table's frame; the view's azimuth from it.
        const glm::dvec3 sun(std::sqrt(1.0 - sunDir.y * sunDir.y), sunDir.y, 0.0);
        std::vector<Sample> samples;
        double brightest = 0.0;
        for (int y = 4; y < image.height; y += 13)
            for (int x = 0; x < image.width; x += 32) {
                const hillaire::SkyViewDirection d = hillaire::skyViewDirection(p, r, {x / (image.width - 1.0), y / (image.height - 1.0)});
                const double sinZenith = std::sqrt(std::max(0.0, 1.0 - d.mu * d.mu));
                const double sinAzimuth = std::sqrt(std::max(0.0, 1.0 - d.cosAzimuth * d.cosAzimuth));
                const glm::dvec3 view(sinZenith * d.cosAzimuth, d.mu, sinZenith * sinAzimuth);
                samples.push_back({texel(image.bytes.data(), static_cast<size_t>(y) * image.width + x), expectedRadiance(start, view, sun),
                                   "texel " + std::to_string(x) + "," + std::to_string(y) + " (mu " + std::to_string(d.mu) + ")"});
                brightest = std::max({brightest, samples.back().expected.r, samples.back().expected.g, samples.back().expected.b});
            }
        Errors errors;
        for (const Sample& sample : samples)
            for (int ch = 0; ch < 3; ++ch) {
                errors.add(std::abs(sample.got[ch] - sample.expected[ch]) / brightest);
                EXPECT_LT(errors.values.back(), kLargest) << c.altitude << " m, sun " << c.sunElevation << ", " << sample.where << ": " << sample.got[ch]
                                                          << " against " << sample.expected[ch];
            }
        const double median = errors.median();
        std::printf("sky view from %.0f m, sun at %.0f degrees: %zu channels, error relative to the brightest: median %.4f, largest %.4f\n",
                    c.altitude, c.sunElevation, errors.values.size(), median, errors.largest());
        EXPECT_LT(median, kMedian);
    }
}

// Sampled froxels (a 4 x 4 grid of columns, slices 1, 8 and the last) from 1 km, looking 10
// degrees down, the sun at 20 degrees: the transmittance from the camera against the reference's
// exp(-optical depth), and the in-scattered light against the reference and the twin.
// Measured: transmittance within 3.4e-5, in-scattering within 0.03% of the brightest.
TEST_F(HillaireCameraTables, AerialPerspectiveMatchesTheReference) {
    constexpr double kTransmittance = 2e-4, kLargest = 0.005;
    makeTables(1000.0, 20.0, -10.0f);
    const Texture3D& inscattering = pass->cameraTables().aerialInscattering;
    const ReadbackVolume light = readTexture3D(device(), context(), inscattering.texture.Get());
    const ReadbackVolume transmittance = readTexture3D(device(), context(), pass->cameraTables().aerialTransmittance.texture.Get());
    const int n = sampling.froxels;
    ASSERT_EQ(light.width, n);
    const glm::dvec3 start(0.0, parameters.physics.earthRadius + 1000.0, 0.0);
    Errors lightErrors;
    double largestTransmittance = 0.0, brightest = 0.0;
    std::vector<Sample> samples;
    for (int j = 2; j < n; j += 9)
        for (int i = 2; i < n; i += 9) {
            const glm::vec4 ndc((i + 0.5f) / n * 2.0f - 1.0f, 1.0f - (j + 0.5f) / n * 2.0f, 1.0f, 1.0f);
            const glm::vec4 farPoint = constants.clipToDirection * ndc;
            const glm::dvec3 view = glm::normalize(glm::dvec3(farPoint) / static_cast<double>(farPoint.w));
            for (const int k : {1, 8, n - 1}) {
                const double distance = hillaire::aerialPerspectiveDistance(k / (n - 1.0));
                if (distance >= reference.rayLength(start, view)) continue;  // beyond the ground: never looked up
                const size_t index = (static_cast<size_t>(k) * n + j) * n + i;
                const glm::dvec3 expectedT = glm::exp(-reference.opticalDepth(reference.netDensity(start, start + view * distance)));
                const glm::dvec3 gotT = texel(transmittance.bytes.data(), index);
                for (int ch = 0; ch < 3; ++ch) {
                    largestTransmittance = std::max(largestTransmittance, std::abs(gotT[ch] - expectedT[ch]));
                    EXPECT_NEAR(gotT[ch], expectedT[ch], kTransmittance) << "froxel " << i << "," << j << "," << k;
                }
                samples.push_back({texel(light.bytes.data(), index), expectedRadiance(start, view, sunDir, distance),
                                   "froxel " + std::to_string(i) + "," + std::to_string(j) + "," + std::to_string(k)});
                brightest = std::max({brightest, samples.back().expected.r, samples.back().expected.g, samples.back().expected.b});
            }
        }
    ASSERT_FALSE(samples.empty());
    for (const Sample& sample : samples)
        for (int ch = 0; ch < 3; ++ch) {
            lightErrors.add(std::abs(sample.got[ch] - sample.expected[ch]) / brightest);
            EXPECT_LT(lightErrors.values.back(), kLargest) << sample.where << ": " << sample.got[ch] << " against " << sample.expected[ch];
        }
    std::printf("aerial perspective: transmittance largest difference %.2e; in-scattering error relative to the brightest: median %.4f, largest "
                "%.4f over %zu channels\n",
                largestTransmittance, lightErrors.median(), lightErrors.largest(), lightErrors.values.size());
}

// Texels of the sky irradiance table: E = sum of L(w) (w . up) dw over the upper hemisphere, L as
// in the sky view's test, on `rings` rings of equal d(cos zenith) by `azimuths` azimuths,
// relative to the brightest expected. Returns the largest error.
double irradianceError(HillaireCameraTables& test, const ReadbackImage& image, const std::vector<glm::ivec2>& texels, int rings, int azimuths,
                       double bound);

TEST_F(HillaireCameraTables, IrradianceMatchesTheFineHemisphereIntegral) {
    // The full tier's (50 s: the reference's single scattering is slow): 12 x 24 directions, the
    // sun from the zenith to just below the horizon, on the ground and at 10 km. Measured 1.5%
    // (the sun at the zenith, where the hemisphere's rings and the pass's 256 directions both
    // sample the aureole coarsely); 6 x 12 rings reached 3.9% there. Watched failing with the
    // cosine left out of the pass (134% on 6 x 12 rings).
    const ReadbackImage image = readTexture2D(device(), context(), tables->tables().irradiance.texture.Get());
    std::vector<glm::ivec2> texels;
    for (const int y : {0, image.height / 2})
        for (const int x : {image.width - 1, image.width * 3 / 4, image.width * 9 / 16, image.width / 2 - 2}) texels.push_back({x, y});
    irradianceError(*this, image, texels, 12, 24, 0.025);
}

double irradianceError(HillaireCameraTables& test, const ReadbackImage& image, const std::vector<glm::ivec2>& texels, int rings, int azimuths,
                       double bound) {
    const AtmosphereParameters& p = test.physics();
    std::vector<Sample> samples;
    double brightest = 0.0;
    for (const glm::ivec2 at : texels) {
        const hillaire::RadiusAndCosine c = hillaire::multipleScatteringCoordinates(p, {at.x / (image.width - 1.0), at.y / (image.height - 1.0)});
        const glm::dvec3 start(0.0, c.r, 0.0), sun(std::sqrt(std::max(0.0, 1.0 - c.mu * c.mu)), c.mu, 0.0);
        glm::dvec3 irradiance(0.0);
        for (int i = 0; i < rings; ++i) {
            const double mu = (i + 0.5) / rings, ring = std::sqrt(1.0 - mu * mu);
            for (int j = 0; j < azimuths; ++j) {
                const double phi = 2.0 * glm::pi<double>() * (j + 0.5) / azimuths;
                irradiance += test.radiance(start, {ring * std::cos(phi), mu, ring * std::sin(phi)}, sun) * mu;
            }
        }
        irradiance *= (1.0 / rings) * (2.0 * glm::pi<double>() / azimuths);
        samples.push_back({HillaireCameraTables::texel(image.bytes.data(), static_cast<size_t>(at.y) * image.width + at.x), irradiance,
                           "h " + std::to_string(c.r - p.earthRadius) + " m, mu_s " + std::to_string(c.mu)});
        brightest = std::max({brightest, irradiance.r, irradiance.g, irradiance.b});
    }
    Errors errors;
    for (const Sample& sample : samples)
        for (int ch = 0; ch < 3; ++ch) {
            errors.add(std::abs(sample.got[ch] - sample.expected[ch]) / brightest);
            EXPECT_LT(errors.values.back(), bound) << sample.where << " channel " << ch << ": " << sample.got[ch] << " against " << sample.expected[ch];
        }
    std::printf("sky irradiance, %d x %d directions: error relative to the brightest: median %.4f, largest %.4f over %zu channels\n", rings, azimuths,
                errors.median(), errors.largest(), errors.values.size());
    return errors.largest();
}

}  // namespace
}  // namespace firmament::test
