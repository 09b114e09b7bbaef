// The epipolar sampling's geometry, refinement and 1D min/max trees (shaders/lightshafts/
// epipolar_geometry.hlsli, refine_samples.hlsl, build_minmax_trees.hlsl) on the WARP device,
// against CPU twins written from Yusov 2013's description: the slices' end points and the
// samples' coordinates with the epipole on the screen, beyond each side, beyond a corner and
// behind the camera; on a synthetic depth profile of alternating near and far bands under a
// sky, which samples are ray marched and each sample's two interpolation sources; the trees
// against a CPU build from the read-back shadow map, in both formats; the march walking the
// trees against the march without them; and no NaN or Inf in any mode.
#include "KnownOccluder.h"
#include "FrameTest.h"
#include "atmosphere/Atmosphere.h"
#include "core/Camera.h"
#include "gpu/CommonStates.h"
#include "gpu/FullscreenPass.h"
#include "lightshafts/EpipolarSampling.h"
#include "lightshafts/LightShafts.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <memory>

namespace firmament::test {
namespace {

constexpr int kWidth = 160, kHeight = 90;
constexpr double kInvalidCoordinate = -1.0e4;

// The frame's constants as the renderer makes them, for a camera and a sun.
gpu::FrameConstants frameConstantsFor(const Camera& camera, const Sun& sun) {
    const glm::mat4 projection = camera.projection(static_cast<float>(kWidth) / kHeight);
    const glm::mat4 viewProjection = projection * camera.view();
    glm::mat4 rotationOnly = camera.view();
    rotationOnly[3] = glm::vec4(0.0f, 0.0f, 0.0f, 1.0f);
    gpu::FrameConstants c{};
    c.viewProjection = viewProjection;
    c.inverseViewProjection = glm::inverse(viewProjection);
    c.clipToDirection = glm::inverse(projection * rotationOnly);
    c.cameraPosition = glm::vec4(camera.position, camera.position.y);
    c.directionToSun = glm::vec4(sun.direction(), 0.0f);
    c.screen = glm::vec4(kWidth, kHeight, 1.0f / kWidth, 1.0f / kHeight);
    c.sunIrradiance = glm::vec4(1.0f);
    c.planet = glm::vec4(6360.0e3f, 0.0f, 0.0f, 0.0f);
    return c;
}

// ---- The CPU twin of the geometry (double precision). ----
struct Bounds {
    double left, bottom, right, top;  // the outermost pixels' centres in NDC
};
Bounds screenBounds() { return {-1.0 + 1.0 / kWidth, -1.0 + 1.0 / kHeight, 1.0 - 1.0 / kWidth, 1.0 - 1.0 / kHeight}; }

// Slice s's exit point: a quarter of the slices on each side, counter-clockwise from the top
// left corner (left side downwards, bottom rightwards, right side upwards, top leftwards).
glm::dvec2 twinExit(int slice, int slices) {
    const Bounds b = screenBounds();
    const double round = 4.0 * slice / slices;
    const int side = std::min(static_cast<int>(std::floor(round)), 3);
    const double p = round - side;
    switch (side) {
        case 0: return {b.left, b.top + (b.bottom - b.top) * p};
        case 1: return {b.left + (b.right - b.left) * p, b.bottom};
        case 2: return {b.right, b.bottom + (b.top - b.bottom) * p};
        default: return {b.right + (b.left - b.right) * p, b.top};
    }
}

// Entry (xy) and exit (zw), or all kInvalidCoordinate.
glm::dvec4 twinSliceEnds(int slice, int slices, int samples, glm::dvec2 epipole, bool onScreen, bool optimize) {
    const Bounds b = screenBounds();
    glm::dvec2 exitPoint = twinExit(slice, slices);
    glm::dvec2 entry = epipole;
    if (!onScreen) {
        // Where the line from the epipole through the exit point crosses the rectangle.
        const glm::dvec2 d = exitPoint - epipole;
        double lo = -1e30, hi = 1e30;
        const double mins[2] = {b.left, b.bottom}, maxs[2] = {b.right, b.top};
        for (int axis = 0; axis < 2; ++axis) {
            if (std::abs(d[axis]) < 1e-12) continue;
            double k0 = (mins[axis] - epipole[axis]) / d[axis], k1 = (maxs[axis] - epipole[axis]) / d[axis];
            if (k0 > k1) std::swap(k0, k1);
            lo = std::max(lo, k0);
            hi = std::min(hi, k1);
        }
        const double length = glm::length(d);
        if (std::abs(hi - 1.0) * length > 1e-4 || (1.0 - lo) * length < 1e-4) return glm::dvec4(kInvalidCoordinate);
        entry = epipole + d * std::max(lo, 0.0);
    }
    if (optimize) {
        const double pixels = glm::length((exitPoint - entry) * glm::dvec2(kWidth, kHeight) * 0.5);
        exitPoint = entry + (exitPoint - entry) * std::max((samples - 1) / std::max(pixels, 1e-3), 1.0);
    }
    return {entry, exitPoint};
}

bool twinOnScreen(glm::dvec2 p, double slack) {
    const Bounds b = screenBounds();
    const double mx = 0.5 / kWidth + slack, my = 0.5 / kHeight + slack;
    return p.x >= b.left - mx && p.x <= b.right + mx && p.y >= b.bottom - my && p.y <= b.top + my;
}

template <typename T>
std::vector<T> texelsOf(const std::vector<std::uint8_t>& bytes) {
    std::vector<T> out(bytes.size() / sizeof(T));
    std::memcpy(out.data(), bytes.data(), out.size() * sizeof(T));
    return out;
}

template <typename T>
std::vector<T> texels(const ReadbackImage& image) {
    std::vector<T> out(static_cast<size_t>(image.width) * image.height);
    std::memcpy(out.data(), image.bytes.data(), out.size() * sizeof(T));
    return out;
}

struct Sources {
    std::uint16_t left, right;
};

class EpipolarSamplingTest : public FrameTest {
protected:
    void SetUp() override {
        FrameTest::SetUp();
        setUpFrame(kWidth, kHeight);
        atmosphereSettings.resolution = LutResolution::Small;
        atmosphereSettings.scatteringOrders = 1;
        atmosphere = std::make_unique<Atmosphere>(device(), TableStorage{});
        epipolar = std::make_unique<EpipolarSampling>(device());
    }

    // Clears the scene to the sky, or draws the band profile (bandWidth pixels wide bands below
    // row horizon, reversed-Z depths near and far).
    void drawDepth(float bandWidth, float horizon, float nearDepth, float farDepth) {
        const float clear[4] = {0.0f, 0.0f, 0.0f, 0.0f};
        context()->ClearRenderTargetView(targets.hdr().rtv.Get(), clear);
        context()->ClearDepthStencilView(targets.depth().dsv.Get(), D3D11_CLEAR_DEPTH, 0.0f, 0);
        if (bandWidth <= 0.0f) return;
        ConstantBuffer<glm::vec4> profile(device());
        profile.update(context(), glm::vec4(bandWidth, horizon, nearDepth, farDepth));
        const auto depthState = states::depthReversed(device());
        const auto rasterizer = states::cullNone(device());
        const D3D11_VIEWPORT viewport{0.0f, 0.0f, static_cast<float>(kWidth), static_cast<float>(kHeight), 0.0f, 1.0f};
        context()->OMSetRenderTargets(0, nullptr, targets.depth().dsv.Get());
        context()->OMSetDepthStencilState(depthState.Get(), 0);
        context()->RSSetState(rasterizer.Get());
        context()->RSSetViewports(1, &viewport);
        context()->IASetInputLayout(nullptr);
        context()->IASetPrimitiveTopology(D3D11_PRIMITIVE_TOPOLOGY_TRIANGLELIST);
        context()->VSSetShader(testShaderLibrary->vertexShader({"lightshafts/depth_profile.hlsl", "vs_main", "vs_5_0", {}}), nullptr, 0);
        context()->PSSetShader(testShaderLibrary->pixelShader({"lightshafts/depth_profile.hlsl", "ps_main", "ps_5_0", {}}), nullptr, 0);
        context()->PSSetConstantBuffers(0, 1, profile.address());
        context()->Draw(3, 0);
        context()->OMSetRenderTargets(0, nullptr, nullptr);
    }

    // Runs every pass of the epipolar sampling for this view (through these cascades, if any).
    void render(const Camera& camera, const Sun& sun, const LightShaftSettings& settings, CascadedShadowMaps* cascades = nullptr) {
        constants = frameConstantsFor(camera, sun);
        frameConstants->update(context(), constants);
        FrameContext frame{device(), context(), *productShaderLibrary, *profiler, targets, frameConstants->get(), constants, camera, sun,
                           0.0, 1.0 / 60.0, true};
        atmosphere->update(frame, atmosphereSettings);
        lookup = atmosphere->scatteringLookup(frame, atmosphereSettings);
        ASSERT_TRUE(lookup.ready);
        const ShadowInputs shadows = cascades ? cascades->inputs() : ShadowInputs{};
        shaftConstants = std::make_unique<ConstantBuffer<gpu::LightShaftConstants>>(device());
        shaftConstants->update(context(), LightShafts::constants(settings, lookup, shadows.resolution));
        ConstantBuffer<gpu::ShadowConstants> noShadows(device());
        noShadows.update(context(), gpu::ShadowConstants{});
        epipolar->render(frame, settings, lookup, shadows, shaftConstants->get(), cascades ? shadows.constants : noShadows.get());
    }

    AtmosphereSettings atmosphereSettings;
    std::unique_ptr<Atmosphere> atmosphere;
    std::unique_ptr<EpipolarSampling> epipolar;
    gpu::FrameConstants constants{};
    ScatteringLookup lookup;
    std::unique_ptr<ConstantBuffer<gpu::LightShaftConstants>> shaftConstants;
};

// Where the sun is for each case: the camera looks along +z (yaw 0) with the sun 10 degrees up
// at azimuth 0, and turns so that the epipole lands where the case says.
struct EpipoleCase {
    const char* label;
    float yaw, pitch;
    bool optimize;
};
const EpipoleCase kEpipoleCases[] = {
    {"on the screen", 12.0f, 16.0f, true},
    {"on the screen, sample locations not optimized", 12.0f, 16.0f, false},
    {"beyond the left side", 50.0f, 10.0f, true},
    {"beyond the right side", -50.0f, 10.0f, true},
    {"below the screen", 0.0f, 40.0f, true},
    {"above the screen", 0.0f, -20.0f, true},
    {"beyond the bottom left corner", 48.0f, 48.0f, true},
    {"behind the camera (the anti-epipole)", 170.0f, -5.0f, true},
};

TEST_F(EpipolarSamplingTest, SliceEndpointsAndSampleCoordinatesMatchTheirCpuTwin) {
    for (const EpipoleCase& c : kEpipoleCases) {
        Camera camera;
        camera.position = {0.0f, 1000.0f, 0.0f};
        camera.yawDegrees = c.yaw;
        camera.pitchDegrees = c.pitch;
        Sun sun;
        sun.elevationDegrees = 10.0f;
        LightShaftSettings settings;
        settings.slices = 64;
        settings.samplesPerSlice = 96;
        settings.optimizeSampleLocations = c.optimize;
        settings.refinementCriterion = RefinementCriterion::Depth;
        drawDepth(0.0f, 0.0f, 0.0f, 0.0f);
        render(camera, sun, settings);
        const auto ends = texels<glm::vec4>(readTexture2D(device(), context(), epipolar->sliceEnds().texture.Get()));
        const auto samples = texels<glm::vec4>(readTexture2D(device(), context(), epipolar->sampleCoordinates().texture.Get()));

        // The epipole the CPU twin starts from: the sun's projection, computed here in double.
        const glm::dmat4 viewProjection(constants.viewProjection);
        const glm::dvec4 clip = viewProjection * glm::dvec4(glm::dvec3(sun.direction()), 0.0);
        glm::dvec2 epipole = glm::dvec2(clip) / clip.w;
        if (glm::length(epipole) > 100.0) epipole *= 100.0 / glm::length(epipole);
        const Bounds b = screenBounds();
        const bool onScreen = std::abs(epipole.x) <= b.right && std::abs(epipole.y) <= b.top;
        const gpu::EpipolarConstants gpuConstants = EpipolarSampling::constants(settings, constants, camera.forward());
        EXPECT_NEAR(gpuConstants.epipole.x, epipole.x, 1e-3 * std::max(1.0, std::abs(epipole.x))) << c.label;
        EXPECT_NEAR(gpuConstants.epipole.y, epipole.y, 1e-3 * std::max(1.0, std::abs(epipole.y))) << c.label;
        EXPECT_EQ(gpuConstants.epipole.w != 0.0f, clip.w < 0.0) << c.label << ": the sun behind the camera";

        int validSlices = 0, validSamples = 0, compared = 0;
        double worst = 0.0;
        for (int s = 0; s < settings.slices; ++s) {
            const glm::dvec4 twin = twinSliceEnds(s, settings.slices, settings.samplesPerSlice, epipole, onScreen, settings.optimizeSampleLocations);
            const bool twinValid = twin.x > 0.5 * kInvalidCoordinate, gpuValid = ends[s].x > 0.5 * kInvalidCoordinate;
            // A slice that touches the screen over less than a thousandth may go either way.
            const bool borderline = std::abs(glm::length(glm::dvec2(twin.z, twin.w) - glm::dvec2(twin.x, twin.y))) < 1e-3;
            if (!borderline) {
                EXPECT_EQ(gpuValid, twinValid) << c.label << ", slice " << s;
            }
            if (!gpuValid || !twinValid) continue;
            ++validSlices;
            for (int k = 0; k < 4; ++k) worst = std::max(worst, std::abs(ends[s][k] - twin[k]) / std::max(1.0, std::abs(twin[k])));
            for (int i = 0; i < settings.samplesPerSlice; ++i) {
                const glm::dvec2 p = glm::mix(glm::dvec2(twin.x, twin.y), glm::dvec2(twin.z, twin.w), static_cast<double>(i) / (settings.samplesPerSlice - 1));
                const glm::vec4 g = samples[static_cast<size_t>(s) * settings.samplesPerSlice + i];
                const bool gpuSample = g.x > 0.5 * kInvalidCoordinate;
                // Samples within 1e-4 of the margin may go either way.
                if (twinOnScreen(p, 1e-4) == twinOnScreen(p, -1e-4)) {
                    EXPECT_EQ(gpuSample, twinOnScreen(p, 0.0)) << c.label << ", slice " << s << " sample " << i;
                }
                if (!gpuSample) continue;
                ++validSamples;
                ++compared;
                worst = std::max(worst, glm::length(glm::dvec2(g.x, g.y) - p));
            }
        }
        std::printf("epipole %s at (%.3f, %.3f): %d valid slices, %d valid samples, largest difference %.2e\n", c.label, epipole.x, epipole.y,
                    validSlices, validSamples, worst);
        EXPECT_LT(worst, 1e-4) << c.label;
        EXPECT_GT(compared, settings.samplesPerSlice) << c.label << ": too few samples on the screen to compare";
        if (onScreen) {
            EXPECT_EQ(validSlices, settings.slices) << c.label << ": with the epipole on the screen every slice is valid";
        }
    }
}

// The refinement's CPU twin: from the samples' camera-space depths as the GPU computed them,
// which neighbours are alike (relative difference below the threshold), then each sample's
// sources between the initial samples (the initial step divided by the density near the
// epipole) without crossing a break.
std::vector<Sources> twinSources(const std::vector<glm::vec4>& samples, const glm::vec4* ends, const LightShaftSettings& settings, glm::dvec2 epipole) {
    const int n = settings.samplesPerSlice;
    std::vector<Sources> out(samples.size(), Sources{0xFFFF, 0xFFFF});
    for (int s = 0; s < settings.slices; ++s) {
        const glm::vec4* row = &samples[static_cast<size_t>(s) * n];
        const auto valid = [&](int i) { return row[i].x > 0.5 * kInvalidCoordinate; };
        std::vector<bool> alike(static_cast<size_t>(n), false);
        for (int i = 0; i + 1 < n; ++i)
            if (valid(i) && valid(i + 1))
                alike[static_cast<size_t>(i)] =
                    std::abs(row[i].z - row[i + 1].z) / std::max({row[i].z, row[i + 1].z, 1.0f}) < settings.depthRefinementThreshold();
        for (int i = 0; i < n; ++i) {
            if (!valid(i)) continue;
            int step = settings.effectiveInitialStep();
            int first = i / step * step;
            const glm::dvec2 blockStart = glm::mix(glm::dvec2(ends[s].x, ends[s].y), glm::dvec2(ends[s].z, ends[s].w), static_cast<double>(first) / (n - 1));
            if (glm::length((blockStart - epipole) * glm::dvec2(kWidth, kHeight) * 0.5) < 0.1 * kHeight) {
                step = std::max(step / settings.epipoleDensity, 1);
                first = i / step * step;
            }
            const int last = std::min(first + step, n - 1);
            int left = i, right = i;
            if (i != first && i != last) {
                while (left > first && alike[static_cast<size_t>(left - 1)]) --left;
                while (right < last && alike[static_cast<size_t>(right)]) ++right;
            }
            if (left == i || right == i) left = right = i;
            out[static_cast<size_t>(s) * n + i] = {static_cast<std::uint16_t>(left), static_cast<std::uint16_t>(right)};
        }
    }
    return out;
}

TEST_F(EpipolarSamplingTest, RefinementMatchesItsCpuTwinOnADepthProfile) {
    Camera camera;
    camera.position = {0.0f, 1000.0f, 0.0f};
    camera.yawDegrees = 12.0f;
    camera.pitchDegrees = 8.0f;
    Sun sun;
    sun.elevationDegrees = 10.0f;
    LightShaftSettings settings;
    settings.slices = 64;
    settings.samplesPerSlice = 128;
    settings.initialStep = 16;
    settings.epipoleDensity = 4;
    settings.refinementCriterion = RefinementCriterion::Depth;
    // Sky above row 30; below, bands 12 pixels wide at reversed-Z depths 0.01 and 0.002 (100 m
    // and 500 m from a camera whose near plane is at 1 m): breaks of a factor of five.
    drawDepth(12.0f, 30.0f, 0.01f, 0.002f);
    render(camera, sun, settings);
    const auto ends = texels<glm::vec4>(readTexture2D(device(), context(), epipolar->sliceEnds().texture.Get()));
    const auto samples = texels<glm::vec4>(readTexture2D(device(), context(), epipolar->sampleCoordinates().texture.Get()));
    const auto sources = texels<Sources>(readTexture2D(device(), context(), epipolar->interpolationSources().texture.Get()));
    const gpu::EpipolarConstants gpuConstants = EpipolarSampling::constants(settings, constants, camera.forward());
    const auto twin = twinSources(samples, ends.data(), settings, glm::dvec2(gpuConstants.epipole.x, gpuConstants.epipole.y));
    int marched = 0, interpolated = 0, mismatches = 0, nearBand = 0;
    for (size_t k = 0; k < twin.size(); ++k) {
        const bool same = sources[k].left == twin[k].left && sources[k].right == twin[k].right;
        if (!same && ++mismatches <= 10)
            ADD_FAILURE() << "slice " << k / settings.samplesPerSlice << " sample " << k % settings.samplesPerSlice << ": sources " << sources[k].left << ", "
                          << sources[k].right << ", the twin's " << twin[k].left << ", " << twin[k].right;
        if (twin[k].left == 0xFFFF) continue;
        const bool self = twin[k].left == k % settings.samplesPerSlice && twin[k].right == twin[k].left;
        marched += self;
        interpolated += !self;
        nearBand += self && samples[k].z < 1.0e7f && (k % settings.samplesPerSlice) % 16 != 0;
    }
    std::printf("%d marched, %d interpolated, %d marched off the initial grid (at breaks or near the epipole); %d mismatches\n", marched, interpolated,
                nearBand, mismatches);
    EXPECT_EQ(mismatches, 0);
    EXPECT_GT(nearBand, settings.slices) << "the bands' breaks should add ray-marching samples";
    EXPECT_GT(interpolated, 2 * marched) << "most samples should be interpolated";

    // The marking lists exactly the samples that are their own sources.
    const auto arguments = readBuffer(device(), context(), epipolar->marchList().arguments());
    EXPECT_EQ(reinterpret_cast<const unsigned*>(arguments.data())[3], static_cast<unsigned>(marched));
}

// The shadow test's square over flat ground, seen from above at 35-degree sun, in four cascades
// over 1 km: the slices cross its shadow.
struct OccluderScene {
    Camera camera;
    Sun sun;
};
OccluderScene occluderScene() {
    OccluderScene scene;
    scene.camera.position = {10.0f, 150.0f, -100.0f};
    scene.camera.yawDegrees = 5.0f;
    scene.camera.pitchDegrees = -25.0f;
    scene.sun.elevationDegrees = 35.0f;
    scene.sun.azimuthDegrees = -30.0f;
    return scene;
}

std::unique_ptr<CascadedShadowMaps> occluderCascades(ID3D11Device* device, ID3D11DeviceContext* context, ShaderLibrary& testShaders,
                                                     const OccluderScene& scene, int resolution) {
    ShadowSettings shadowSettings;
    shadowSettings.cascades = 4;
    shadowSettings.distanceKm = 1.0f;
    shadowSettings.resolution = resolution == 512 ? ShadowMapResolution::R512 : ShadowMapResolution::R1024;
    auto shadows = std::make_unique<CascadedShadowMaps>(device);
    shadows->update(context, scene.camera, static_cast<float>(kWidth) / kHeight, glm::dvec3(scene.sun.direction()), shadowSettings, 2000.0);
    drawKnownOccluder(device, context, testShaders, *shadows);
    return shadows;
}

// The CPU build of one tree's leaf k, mirroring the shader's arithmetic in float: every atlas
// texel the comparison filter reads between steps k and k + 1, a quarter texel to spare.
glm::vec2 twinLeaf(const std::vector<float>& atlas, int atlasWidth, int atlasHeight, int tilesPerRow, int resolution, glm::vec4 line, int c, int k,
                   bool unorm) {
    const glm::vec2 origin(line.x, line.y), step(line.z, line.w);
    const glm::vec2 a = origin + step * static_cast<float>(k), b = a + step;
    if (glm::any(glm::lessThan(glm::min(a, b), glm::vec2(0.0f))) || glm::any(glm::greaterThan(glm::max(a, b), glm::vec2(1.0f)))) return {0.0f, 1.0f};
    const glm::vec2 tile(static_cast<float>(c % tilesPerRow), static_cast<float>(c / tilesPerRow));
    const glm::vec2 inverseTiles(1.0f / tilesPerRow, 1.0f / (atlasHeight / resolution));
    const glm::vec2 atlasSize(static_cast<float>(atlasWidth), static_cast<float>(atlasHeight));
    const glm::vec2 pa = (a + tile) * inverseTiles * atlasSize, pb = (b + tile) * inverseTiles * atlasSize;
    const glm::ivec2 lo = glm::max(glm::ivec2(glm::floor(glm::min(pa, pb) - 0.5f - 0.25f)), glm::ivec2(0));
    const glm::ivec2 hi = glm::min(glm::ivec2(glm::floor(glm::max(pa, pb) - 0.5f + 0.25f)) + 1, glm::ivec2(atlasWidth - 1, atlasHeight - 1));
    glm::vec2 bounds(1.0f, 0.0f);
    for (int y = lo.y; y <= hi.y; ++y)
        for (int x = lo.x; x <= hi.x; ++x) {
            const float depth = atlas[static_cast<size_t>(y) * atlasWidth + x];
            bounds = {std::min(bounds.x, depth), std::max(bounds.y, depth)};
        }
    if (unorm) bounds = glm::vec2(std::floor(bounds.x * 65535.0f), std::ceil(bounds.y * 65535.0f)) / 65535.0f;
    return bounds;
}

TEST_F(EpipolarSamplingTest, MinMaxTreesMatchACpuBuildFromTheShadowMap) {
    const OccluderScene scene = occluderScene();
    constexpr int resolution = 512;
    auto shadows = occluderCascades(device(), context(), *testShaderLibrary, scene, resolution);
    ComPtr<ID3D11Resource> atlasResource;
    shadows->inputs().map->GetResource(&atlasResource);
    ComPtr<ID3D11Texture2D> atlasTexture;
    ASSERT_HRESULT_SUCCEEDED(atlasResource.As(&atlasTexture));
    const ReadbackImage atlasImage = readTexture2D(device(), context(), atlasTexture.Get());
    const auto atlas = texels<float>(atlasImage);
    const int tilesPerRow = atlasImage.width / resolution;
    for (const MinMaxFormat format : {MinMaxFormat::Unorm16, MinMaxFormat::Float32}) {
        const bool unorm = format == MinMaxFormat::Unorm16;
        LightShaftSettings settings;
        settings.slices = 32;
        settings.samplesPerSlice = 64;
        settings.firstCascade = 0;
        settings.minMaxFormat = format;
        drawDepth(0.0f, 0.0f, 0.0f, 0.0f);
        render(scene.camera, scene.sun, settings, shadows.get());
        const auto lines = texels<glm::vec4>(readTexture2D(device(), context(), epipolar->sliceLines().texture.Get()));
        const auto ends = texels<glm::vec4>(readTexture2D(device(), context(), epipolar->sliceEnds().texture.Get()));
        int validSlices = 0;
        for (int slice = 0; slice < settings.slices; ++slice) validSlices += ends[static_cast<size_t>(slice)].x > 0.5 * kInvalidCoordinate;
        const ReadbackImage treeImage = readTexture2D(device(), context(), epipolar->minMaxTrees().texture.Get());
        ASSERT_EQ(treeImage.width, 2 * resolution);
        ASSERT_EQ(treeImage.height, settings.slices * 4);
        const auto tree = [&](int row, int column) {
            const size_t i = static_cast<size_t>(row) * treeImage.width + column;
            if (!unorm) {
                glm::vec2 v;
                std::memcpy(&v, treeImage.bytes.data() + i * 8, 8);
                return v;
            }
            std::uint16_t u[2];
            std::memcpy(u, treeImage.bytes.data() + i * 4, 4);
            return glm::vec2(u[0], u[1]) / 65535.0f;
        };
        int mismatches = 0, overSquare = 0, validLines = 0;
        for (int c = 0; c < 4; ++c)
            for (int slice = 0; slice < settings.slices; ++slice) {
                const int row = c * settings.slices + slice;
                const glm::vec4 line = lines[static_cast<size_t>(c) * settings.slices + slice];
                const bool valid = line.x > -1.0e3f;
                validLines += valid;
                std::vector<glm::vec2> level(static_cast<size_t>(resolution));
                for (int k = 0; k < resolution; ++k)
                    level[static_cast<size_t>(k)] = valid ? twinLeaf(atlas, atlasImage.width, atlasImage.height, tilesPerRow, resolution, line, c, k, unorm)
                                                          : glm::vec2(0.0f, 1.0f);
                int offset = 0;
                for (int count = resolution; count >= 1; count /= 2) {
                    for (int k = 0; k < count; ++k) {
                        const glm::vec2 expected = level[static_cast<size_t>(k)], actual = tree(row, offset + k);
                        overSquare += expected.x < 1.0f && expected.y <= 1.0f && expected.x > 0.0f;
                        if (actual != expected && ++mismatches <= 8)
                            ADD_FAILURE() << (unorm ? "16-bit" : "32-bit") << " cascade " << c << " slice " << slice << " level offset " << offset << " entry " << k
                                          << ": (" << actual.x << ", " << actual.y << "), the CPU's (" << expected.x << ", " << expected.y << ")";
                    }
                    for (int k = 0; k < count / 2; ++k)
                        level[static_cast<size_t>(k)] = {std::min(level[2 * k].x, level[2 * k + 1].x), std::max(level[2 * k].y, level[2 * k + 1].y)};
                    offset += count;
                }
            }
        std::printf("%s trees: %d slice lines (%d valid slices), %d entries over the square, %d mismatches\n", unorm ? "16-bit unorm" : "32-bit float",
                    validLines, validSlices, overSquare, mismatches);
        EXPECT_EQ(mismatches, 0);
        EXPECT_EQ(validLines, 4 * validSlices) << "every valid slice's line should cross every cascade";
        EXPECT_GT(overSquare, 100) << "the lines should cross the square";
    }
}

// Marching with the trees gives what marching without them gives, within 10^-3 relative, in
// either format: the trees only let the march take proven stretches at once. Compared are the
// march's own results for every sample of the frame (lit length and first lit point, through
// tests/shaders/lightshafts/tree_march_probe.hlsl): the in-scattering that eq. 8 makes of them
// can jump by a percent where a look-up crosses a row of the packed table, for a millimetre's
// difference in where a lit section ends.
TEST_F(EpipolarSamplingTest, TreesChangeSpeedNotTheResult) {
    const OccluderScene scene = occluderScene();
    auto shadows = occluderCascades(device(), context(), *testShaderLibrary, scene, 1024);
    const ShadowInputs in = shadows->inputs();
    LightShaftSettings settings;
    settings.slices = 64;
    settings.samplesPerSlice = 128;
    settings.firstCascade = 0;
    const size_t count = static_cast<size_t>(settings.slices) * settings.samplesPerSlice;
    const auto march = [&](bool trees) {
        gpu::EpipolarConstants c = EpipolarSampling::constants(settings, constants, scene.camera.forward(), in);
        if (!trees) c.trees.x = 0;
        ConstantBuffer<gpu::EpipolarConstants> epipolarConstants(device());
        epipolarConstants.update(context(), c);
        ID3D11Buffer* buffers[] = {frameConstants->get(), lookup.atmosphere, shaftConstants->get(), in.constants, epipolarConstants.get()};
        ID3D11ShaderResourceView* inputs[19] = {};
        inputs[2] = lookup.netDensity;
        inputs[3] = lookup.singleScattering;
        inputs[4] = lookup.highOrderScattering;
        inputs[5] = lookup.multipleScattering;
        inputs[6] = in.map;
        inputs[8] = epipolar->sliceEnds().srv.Get();
        inputs[9] = epipolar->sampleCoordinates().srv.Get();
        inputs[17] = epipolar->sliceLines().srv.Get();
        inputs[18] = epipolar->minMaxTrees().srv.Get();
        ID3D11SamplerState* samplers[] = {lookup.linearClamp, in.comparison};
        auto output = structuredBuffer(std::vector<glm::vec4>(count, glm::vec4(0.0f)), true);
        ComPtr<ID3D11UnorderedAccessView> uav;
        EXPECT_HRESULT_SUCCEEDED(device()->CreateUnorderedAccessView(output.Get(), nullptr, &uav));
        context()->CSSetConstantBuffers(0, 5, buffers);
        context()->CSSetShaderResources(0, 19, inputs);
        context()->CSSetSamplers(0, 2, samplers);
        context()->CSSetUnorderedAccessViews(0, 1, uav.GetAddressOf(), nullptr);
        context()->CSSetShader(testShaderLibrary->computeShader({"lightshafts/tree_march_probe.hlsl", "main", "cs_5_0", {}}), nullptr, 0);
        context()->Dispatch(static_cast<UINT>(settings.samplesPerSlice / 64), static_cast<UINT>(settings.slices), 1);
        ID3D11ShaderResourceView* noInputs[19] = {};
        ID3D11UnorderedAccessView* noOutput = nullptr;
        context()->CSSetShaderResources(0, 19, noInputs);
        context()->CSSetUnorderedAccessViews(0, 1, &noOutput, nullptr);
        return texelsOf<glm::vec4>(readBuffer(device(), context(), output.Get()));
    };
    for (const MinMaxFormat format : {MinMaxFormat::Unorm16, MinMaxFormat::Float32}) {
        settings.minMaxFormat = format;
        drawDepth(0.0f, 0.0f, 0.0f, 0.0f);
        render(scene.camera, scene.sun, settings, shadows.get());
        const std::vector<glm::vec4> with = march(true), without = march(false);
        ASSERT_EQ(with.size(), count);
        double worst = 0.0;
        int marched = 0, shadowed = 0;
        for (size_t i = 0; i < count; ++i) {
            const glm::vec4 a = with[i], b = without[i];
            if (b.x < 0.0f) continue;
            const double length = std::max(static_cast<double>(b.w - b.z), 1e-3);
            if (length <= 1e-3) continue;
            ++marched;
            shadowed += b.x < 0.999f * (b.w - b.z);
            worst = std::max({worst, std::abs(static_cast<double>(a.x) - b.x) / length, std::abs(static_cast<double>(a.y) - b.y) / length});
        }
        std::printf("%s trees: %d samples marched, %d of them through shadow; largest difference of lit length or first lit point %.2e of the marched length\n",
                    format == MinMaxFormat::Unorm16 ? "16-bit unorm" : "32-bit float", marched, shadowed, worst);
        EXPECT_LT(worst, 1e-3);
        EXPECT_GT(shadowed, marched / 20) << "the samples should cross the square's shadow";
    }
}

// The three cascade processing modes draw the same light: the cascade-by-cascade modes add the
// cascades' parts in the order the single pass adds them, with the same arithmetic; with single
// scattering integrated too (its optical depth restarts at each cascade from the table in every
// mode).
TEST_F(EpipolarSamplingTest, CascadeProcessingModesDrawTheSameLight) {
    const OccluderScene scene = occluderScene();
    auto shadows = occluderCascades(device(), context(), *testShaderLibrary, scene, 512);
    LightShaftSettings settings;
    settings.slices = 64;
    settings.samplesPerSlice = 128;
    settings.firstCascade = 0;
    for (const SingleScatteringMode single : {SingleScatteringMode::Table, SingleScatteringMode::Integration}) {
        atmosphereSettings.singleScattering = single;
        std::vector<std::uint8_t> reference;
        for (const CascadeProcessing mode : {CascadeProcessing::SinglePass, CascadeProcessing::MultiPass, CascadeProcessing::Instanced}) {
            settings.cascadeProcessing = mode;
            drawDepth(0.0f, 0.0f, 0.0f, 0.0f);
            render(scene.camera, scene.sun, settings, shadows.get());
            const std::vector<std::uint8_t> light = readTexture2D(device(), context(), epipolar->interpolatedInscattering().texture.Get()).bytes;
            if (mode == CascadeProcessing::SinglePass) {
                reference = light;
                int lit = 0;
                const auto* bits = reinterpret_cast<const std::uint16_t*>(light.data());
                for (size_t i = 0; i < light.size() / 2; ++i) lit += (bits[i] & 0x7FFF) != 0 && i % 4 != 3;
                EXPECT_GT(lit, static_cast<int>(light.size() / 16)) << "the samples should see light";
                continue;
            }
            size_t differing = 0;
            for (size_t i = 0; i < light.size(); i += 2) differing += std::memcmp(&light[i], &reference[i], 2) != 0;
            std::printf("SS %s, %s: %zu of %zu components differ from the single pass\n", single == SingleScatteringMode::Table ? "LUT" : "Integration",
                        std::string(kCascadeProcessingNames[static_cast<size_t>(mode)]).c_str(), differing, light.size() / 2);
            EXPECT_EQ(differing, 0u) << kCascadeProcessingNames[static_cast<size_t>(mode)];
        }
    }
}

// Every render mode, with the sun high, low, setting and below the horizon, from the ground to
// orbit, over the band profile (depth breaks, sky, the ground) with correction at depth breaks:
// every pixel of the frame is finite and not negative.
TEST_F(EpipolarSamplingTest, NoNanOrInfInAnyModeSunOrAltitude) {
    LightShaftSettings settings;
    settings.slices = 64;
    settings.samplesPerSlice = 64;
    settings.initialStep = 8;
    settings.correctDepthBreaks = true;
    settings.refinementThreshold = 0.5f;
    int frames = 0, bad = 0;
    for (const SingleScatteringMode single : {SingleScatteringMode::None, SingleScatteringMode::Integration, SingleScatteringMode::Table})
        for (const MultipleScatteringMode multiple : {MultipleScatteringMode::None, MultipleScatteringMode::Occluded, MultipleScatteringMode::Unoccluded})
            for (const float elevation : {89.0f, 20.0f, 1.0f, -6.0f})
                for (const float altitude : {2.0f, 3000.0f, 40.0e3f, 200.0e3f}) {
                    atmosphereSettings.singleScattering = single;
                    atmosphereSettings.multipleScattering = multiple;
                    Camera camera;
                    camera.position = {0.0f, altitude, 0.0f};
                    camera.pitchDegrees = altitude > 100.0e3f ? -60.0f : 5.0f;
                    Sun sun;
                    sun.elevationDegrees = elevation;
                    sun.azimuthDegrees = 20.0f;
                    drawDepth(10.0f, 40.0f, 0.01f, 0.0005f);
                    render(camera, sun, settings);
                    const ReadbackImage hdr = readTexture2D(device(), context(), targets.hdr().texture.Get());
                    const auto* bits = reinterpret_cast<const std::uint16_t*>(hdr.bytes.data());
                    int badHere = 0;
                    for (size_t i = 0; i < static_cast<size_t>(kWidth) * kHeight * 4; ++i) {
                        // Half floats: all exponent bits set is Inf or NaN; the sign bit on a non-zero value is negative.
                        const bool notFinite = (bits[i] & 0x7C00) == 0x7C00, negative = (bits[i] & 0x8000) != 0 && (bits[i] & 0x7FFF) != 0;
                        badHere += notFinite || negative;
                    }
                    if (badHere > 0 && ++bad <= 10)
                        ADD_FAILURE() << badHere << " components not finite or negative: SS " << static_cast<int>(single) << ", MS "
                                      << static_cast<int>(multiple) << ", sun " << elevation << " degrees, altitude " << altitude << " m";
                    ++frames;
                }
    std::printf("%d frames, %d with a component not finite or negative\n", frames, bad);
    EXPECT_EQ(bad, 0);
}

}  // namespace
}  // namespace firmament::test
