// The three atmosphere models drawn by the atmosphere technique (src/atmosphere/Atmosphere) over
// the grid the models are scored on: altitudes 0, 1, 10, 40 and 400 km, the sun at 60, 20, 5,
// 0, -4, -8, -12 and -18 degrees, the default constants and a hazy set (aerosol density 4).
// Every pixel of the sky part (nothing drawn) and of the aerial perspective (geometry 10 km
// away everywhere) must be finite and not negative, for each model.
#include "FrameTest.h"
#include "atmosphere/Atmosphere.h"
#include "core/Camera.h"
#include "gpu/Readback.h"

#include <glm/gtc/packing.hpp>

#include <cmath>
#include <cstring>

namespace firmament::test {
namespace {

constexpr int kWidth = 48, kHeight = 32;

class AtmosphereModels : public FrameTest {
protected:
    void SetUp() override {
        FrameTest::SetUp();
        setUpFrame(kWidth, kHeight);
    }

    FrameContext frame() {
        return frameContext(constants, camera, sun);
    }

    // The frame's constants for the camera and sun, as the renderer makes them.
    void place(float altitude, float sunElevation) {
        camera.position = glm::vec3(0.0f, altitude, 0.0f);
        camera.yawDegrees = 60.0f;  // the sun's azimuth is 30 degrees: it lies in the frame's left half
        camera.pitchDegrees = altitude > 1.0e5f ? -60.0f : 0.0f;
        camera.verticalFovDegrees = 90.0f;
        camera.nearPlane = 1.0f;
        sun.elevationDegrees = sunElevation;
        sun.azimuthDegrees = 30.0f;
        const glm::mat4 projection = camera.projection(static_cast<float>(kWidth) / kHeight);
        glm::mat4 rotationOnly = camera.view();
        rotationOnly[3] = glm::vec4(0.0f, 0.0f, 0.0f, 1.0f);
        constants = {};
        constants.viewProjection = projection * camera.view();
        constants.inverseViewProjection = glm::inverse(constants.viewProjection);
        constants.clipToDirection = glm::inverse(projection * rotationOnly);
        constants.cameraPosition = glm::vec4(camera.position, camera.position.y);
        constants.directionToSun = glm::vec4(sun.direction(), 0.0f);
        constants.screen = glm::vec4(kWidth, kHeight, 1.0f / kWidth, 1.0f / kHeight);
        constants.sunIrradiance = glm::vec4(1.0f);
        constants.planet = glm::vec4(static_cast<float>(AtmosphereParameters{}.earthRadius), 0.0f, 0.0f, 0.0f);
        frameConstants->update(context(), constants);
    }

    // The HDR frame's pixels that are not finite or are negative, as text ("" when none).
    std::string badPixels() {
        const ReadbackImage image = readTexture2D(device(), context(), targets.hdr().texture.Get());
        std::string bad;
        const size_t texelBytes = image.bytes.size() / (static_cast<size_t>(image.width) * image.height);
        for (int y = 0; y < image.height; ++y)
            for (int x = 0; x < image.width; ++x)
                for (int c = 0; c < 3; ++c) {
                    const float v = channel(image, x, y, c, texelBytes);
                    if ((!std::isfinite(v) || v < 0.0f) && bad.size() < 200) bad += std::to_string(x) + "," + std::to_string(y) + ": " + std::to_string(v) + "; ";
                }
        return bad;
    }

    static float channel(const ReadbackImage& image, int x, int y, int c, size_t texelBytes) {
        const std::uint8_t* texel = image.bytes.data() + (static_cast<size_t>(y) * image.width + x) * texelBytes;
        if (texelBytes == 16) {
            float v;
            std::memcpy(&v, texel + 4 * c, 4);
            return v;
        }
        std::uint16_t h;  // half float
        std::memcpy(&h, texel + 2 * c, 2);
        return glm::unpackHalf1x16(h);
    }

    gpu::FrameConstants constants{};
    Camera camera;
    Sun sun;
};

TEST_F(AtmosphereModels, NoModelGivesNaNOrNegativeRadianceOverTheGrid) {
    Atmosphere atmosphere(device(), TableStorage{});
    const float clearScene[4] = {0.05f, 0.05f, 0.05f, 1.0f};
    int frames = 0;
    for (const float aerosols : {1.0f, 4.0f})
        for (const AtmosphereModel model : {AtmosphereModel::Yusov2013, AtmosphereModel::Bruneton2008, AtmosphereModel::Hillaire2020}) {
            AtmosphereSettings settings;
            settings.model = model;
            settings.aerosolDensity = aerosols;
            for (const float altitude : {0.0f, 1.0e3f, 1.0e4f, 4.0e4f, 4.0e5f})
                for (const float elevation : {60.0f, 20.0f, 5.0f, 0.0f, -4.0f, -8.0f, -12.0f, -18.0f}) {
                    place(altitude, elevation);
                    FrameContext f = frame();
                    atmosphere.update(f, settings);
                    ASSERT_TRUE(atmosphere.ready(settings));
                    // The sky part over the whole frame (nothing drawn), then the aerial
                    // perspective over geometry 10 km away everywhere (reversed Z: near / distance).
                    for (const float depth : {0.0f, 1.0e-4f}) {
                        context()->ClearRenderTargetView(targets.hdr().rtv.Get(), clearScene);
                        context()->ClearDepthStencilView(targets.depth().dsv.Get(), D3D11_CLEAR_DEPTH, depth, 0);
                        if (depth == 0.0f) atmosphere.renderSky(f, settings);
                        else atmosphere.renderAerialPerspective(f, settings);
                        const std::string bad = badPixels();
                        EXPECT_TRUE(bad.empty()) << kAtmosphereModelNames[static_cast<size_t>(model)] << ", aerosols " << aerosols << ", " << altitude
                                                 << " m, sun " << elevation << (depth == 0.0f ? ", sky: " : ", aerial perspective: ") << bad;
                        ++frames;
                    }
                }
        }
    EXPECT_EQ(frames, 2 * 3 * 5 * 8 * 2);
}

}  // namespace
}  // namespace firmament::test
