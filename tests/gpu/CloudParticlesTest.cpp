// The clouds' particles on the WARP device (src/clouds/CloudParticles.h, shaders/clouds/):
// the density map, the valid cells and the generated particles against the CPU twin
// (src/clouds/CloudField.h) for fixed seeds, cameras and times; the GPU sort's back-to-front
// order; and finite particles over the layer's places and every control's extremes.
#include "FrameTest.h"
#include "clouds/CloudField.h"
#include "clouds/CloudParticles.h"
#include "clouds/CloudReference.h"
#include "clouds/CloudShadowMap.h"
#include "clouds/LightSpace.h"
#include "clouds/ParticleOpacity.h"
#include "clouds/ParticleTables.h"
#include "core/Camera.h"
#include "frame/FrameContext.h"
#include "reference/CloudFieldTwin.h"
#include "reference/CloudPathTracer.h"
#include "reference/DeckDiffusion.h"
#include "reference/SunColumnTwin.h"
#include "tables/StagedComputation.h"

#include <gtest/gtest.h>

#include <glm/geometric.hpp>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <cstring>
#include <map>
#include <random>
#include <tuple>

namespace firmament::test {
namespace {

constexpr int kWidth = 96, kHeight = 54;
constexpr float kEarthRadius = 6360.0e3f;

template <typename T>
std::vector<T> fromBytes(const std::vector<std::uint8_t>& bytes, size_t count) {
    std::vector<T> values(count);
    std::memcpy(values.data(), bytes.data(), count * sizeof(T));
    return values;
}

class CloudParticlesTest : public FrameTest {
protected:
    void SetUp() override {
        FrameTest::SetUp();
        setUpFrame(kWidth, kHeight);
        clouds = std::make_unique<CloudParticles>(device());
    }

    // One update for a camera at `position` looking along +z, at `seconds`.
    void generate(const CloudSettings& settings, glm::vec3 position, double seconds) {
        FrameContext frame = frameAt(position, seconds);
        clouds->update(frame, settings);
    }

    // The frame for a camera at `position` looking along +z, at `seconds`.
    FrameContext frameAt(glm::vec3 position, double seconds) {
        camera.position = position;
        camera.pitchDegrees = 10.0f;
        const glm::mat4 viewProjection = camera.projection(static_cast<float>(kWidth) / kHeight) * camera.view();
        constants = gpu::FrameConstants{};
        constants.viewProjection = viewProjection;
        constants.inverseViewProjection = glm::inverse(viewProjection);
        constants.cameraPosition = glm::vec4(position, position.y);
        constants.directionToSun = glm::vec4(sun.direction(), 0.0f);
        constants.screen = glm::vec4(kWidth, kHeight, 1.0f / kWidth, 1.0f / kHeight);
        constants.planet = glm::vec4(kEarthRadius, 0.0f, 0.0f, 0.0f);
        frameConstants->update(context(), constants);
        return FrameContext{device(), context(), *productShaderLibrary, *profiler, targets, frameConstants->get(), constants, camera, sun,
                            seconds, 1.0 / 60.0, true};
    }

    std::vector<unsigned> arguments() { return fromBytes<unsigned>(readBuffer(device(), context(), clouds->particleArguments()), 8); }
    unsigned particleCount() { return std::min(arguments()[3], clouds->capacity()); }
    std::vector<gpu::CloudParticle> particles(unsigned count) {
        return fromBytes<gpu::CloudParticle>(readBuffer(device(), context(), clouds->particles()), count);
    }
    std::vector<glm::uvec2> sortedKeys(unsigned count) { return fromBytes<glm::uvec2>(readBuffer(device(), context(), clouds->sortedKeys()), count); }
    std::vector<float> densityMap() {
        const ReadbackImage image = readTexture2D(device(), context(), clouds->densityMap());
        return fromBytes<float>(image.bytes, static_cast<size_t>(image.width) * image.height);
    }
    CloudFieldModel model(const CloudSettings& settings) {
        std::vector<std::uint32_t> packed;
        for (const CloudCell& cell : CloudGrid(settings).cells()) packed.push_back(packCloudCell(cell));
        return modelCloudField(clouds->constants(), packed, cloudDensityMap(settings.densityResolution), camera.position, kEarthRadius);
    }

    // A small dense field (2 rings of 32 cells out to 20 km) at `cloudiness`, generated for a camera
    // at `position` under a sun 35 degrees up at azimuth 60, with the particle tables computed:
    // the particles as the CPU model takes them (empty when the field holds 500 or fewer).
    struct DenseField {
        CloudSettings settings;
        std::unique_ptr<ParticleTablePrecomputation> tables;
        std::vector<ModelParticle> model;
    };
    // The test's frame is then frameAt(position, 0.0) again.
    DenseField denseField(float cloudiness, glm::vec3 position);

    void expectFieldMatches(const CloudSettings& settings, const char* what);
    void expectBackToFront(const char* what);

    Camera camera;
    Sun sun;
    gpu::FrameConstants constants{};
    std::unique_ptr<CloudParticles> clouds;
};

CloudParticlesTest::DenseField CloudParticlesTest::denseField(float cloudiness, glm::vec3 position) {
    DenseField field;
    field.settings.rings = 2;
    field.settings.ringDimension = 32;
    field.settings.particleDistance = 2.0e4f;
    field.settings.cloudiness = cloudiness;
    sun.elevationDegrees = 35.0f;
    sun.azimuthDegrees = 60.0f;
    const ParticleTableParameters tableParameters;
    field.tables = std::make_unique<ParticleTablePrecomputation>(device(), tableParameters);
    field.tables->runAll(context(), *productShaderLibrary);
    const OpticalDepthTableSize& n = tableParameters.opticalDepth;
    FrameContext frame = frameAt(position, 0.0);
    clouds->update(frame, field.settings, glm::vec4(n.entryZenith, n.entryAzimuth, n.directionZenith, n.directionAzimuth));
    const unsigned count = particleCount();
    if (count <= 500u) return field;
    for (const gpu::CloudParticle& p : particles(count))
        field.model.push_back({glm::vec3(p.centre), p.centre.w, p.shape.x, p.shape.y, p.shape.z, 0, 0, 0});
    return field;
}

TEST_F(CloudParticlesTest, TheDensityMapMatchesTheCpuTwin) {
    for (int resolution : {128, 1024}) {
        CloudSettings settings;
        settings.rings = 1;
        settings.ringDimension = 16;
        settings.densityResolution = resolution;
        generate(settings, glm::vec3(0.0f, 1500.0f, 0.0f), 0.0);
        const std::vector<float> gpuMap = densityMap();
        const std::vector<float> cpuMap = cloudDensityMap(resolution);
        ASSERT_EQ(gpuMap.size(), cpuMap.size());
        float worst = 0.0f;
        for (size_t k = 0; k < cpuMap.size(); ++k) worst = std::max(worst, std::abs(gpuMap[k] - cpuMap[k]));
        EXPECT_LT(worst, 2e-5f) << resolution;
    }
}

// The valid cells and the particles of the GPU against the twin's, cell by cell and particle by
// particle. A cell may differ only where the twin finds it within float rounding of a threshold.
void CloudParticlesTest::expectFieldMatches(const CloudSettings& settings, const char* what) {
    const CloudFieldModel cpu = model(settings);
    const WorkList& list = clouds->validCells();
    const unsigned validCount = fromBytes<unsigned>(readBuffer(device(), context(), list.arguments()), 8)[3];
    std::vector<unsigned> gpuValid = fromBytes<unsigned>(readBuffer(device(), context(), list.items()), validCount);
    std::sort(gpuValid.begin(), gpuValid.end());
    std::vector<unsigned> borderline;
    std::vector<unsigned> mismatched;
    std::set_symmetric_difference(gpuValid.begin(), gpuValid.end(), cpu.validCells.begin(), cpu.validCells.end(), std::back_inserter(mismatched));
    for (unsigned cell : mismatched) {
        const bool nearThreshold = std::abs(cpu.coverage[cell]) < 1e-4f || std::abs(cpu.reach[cell] - settings.particleDistance) < 1.0f;
        EXPECT_TRUE(nearThreshold) << what << ": cell " << cell << " differs (coverage " << cpu.coverage[cell] << ", reach " << cpu.reach[cell] << ")";
    }
    EXPECT_GT(cpu.validCells.size(), 0u) << what;

    const unsigned count = particleCount();
    const std::vector<gpu::CloudParticle> gpuParticles = particles(count);
    EXPECT_NEAR(static_cast<double>(count), static_cast<double>(cpu.particles.size()), 4.0 * mismatched.size()) << what;
    auto key = [](glm::vec3 c) { return std::make_tuple(std::lround(c.x / 4.0f), std::lround(c.y / 4.0f), std::lround(c.z / 4.0f)); };
    std::map<std::tuple<long, long, long>, const gpu::CloudParticle*> byPlace;
    for (const gpu::CloudParticle& p : gpuParticles) byPlace[key(glm::vec3(p.centre))] = &p;
    size_t matched = 0;
    for (const ModelParticle& m : cpu.particles) {
        auto found = byPlace.find(key(m.centre));
        if (found == byPlace.end()) continue;  // on a 4 m boundary: rare; counted below
        const gpu::CloudParticle& g = *found->second;
        ++matched;
        EXPECT_LT(glm::length(glm::vec3(g.centre) - m.centre), 2.0f) << what;
        // Radii within float rounding of the cell's size (the coverage's rounding scales them).
        const float size = std::ldexp(clouds->constants().grid.x, m.ring);
        EXPECT_NEAR(g.centre.w, m.horizontalRadius, 2e-5f * size) << what;
        EXPECT_NEAR(g.shape.x, m.verticalRadius, 2e-5f * size) << what;
        EXPECT_NEAR(g.shape.y, m.density, 1e-4f) << what;
        EXPECT_NEAR(g.shape.z, m.azimuth, 1e-5f) << what;
        EXPECT_EQ(static_cast<int>(g.shape.w), m.ring) << what;
    }
    EXPECT_GT(matched, cpu.particles.size() * 99 / 100) << what;
}

TEST_F(CloudParticlesTest, ValidCellsAndParticlesMatchTheCpuTwin) {
    CloudSettings small;
    small.rings = 3;
    small.ringDimension = 32;
    small.particleDistance = 3.0e4f;
    generate(small, glm::vec3(12345.0f, 1500.0f, -6789.0f), 37.0);
    expectFieldMatches(small, "small grid");
    // The sample's defaults, another place and time, over the layer.
    generate(CloudSettings{}, glm::vec3(-2.5e5f, 4200.0f, 8.0e4f), 1234.5);
    expectFieldMatches(CloudSettings{}, "defaults");
}

// Every consecutive pair is drawn back to front, each particle once, and each key holds the
// particle's distance from the camera.
void CloudParticlesTest::expectBackToFront(const char* what) {
    const unsigned count = particleCount();
    ASSERT_GT(count, 0u) << what;
    const std::vector<glm::uvec2> keys = sortedKeys(count);
    const std::vector<gpu::CloudParticle> written = particles(count);
    std::vector<bool> seen(count, false);
    const glm::vec3 eye = camera.position;
    for (unsigned k = 0; k < count; ++k) {
        ASSERT_LT(keys[k].y, count) << what;
        EXPECT_FALSE(seen[keys[k].y]) << what << ": particle " << keys[k].y << " twice";
        seen[keys[k].y] = true;
        float distance;
        std::memcpy(&distance, &keys[k].x, sizeof(float));
        EXPECT_NEAR(distance, glm::length(glm::vec3(written[keys[k].y].centre) - eye), 1e-3f * distance) << what;
        if (k > 0 && keys[k - 1].x < keys[k].x) {
            ADD_FAILURE() << what << ": entry " << k << " is farther than the one before it";
            return;
        }
    }
}

TEST_F(CloudParticlesTest, TheSortPutsEveryParticleBackToFront) {
    CloudSettings settings;
    settings.rings = 4;
    settings.ringDimension = 64;
    settings.particleDistance = 6.0e4f;
    // Below, inside and above the layer; then a small field of less than one block.
    generate(settings, glm::vec3(0.0f, 500.0f, 0.0f), 0.0);
    expectBackToFront("below the layer");
    generate(settings, glm::vec3(3.0e4f, 3000.0f, -1.0e4f), 60.0);
    expectBackToFront("inside the layer");
    generate(settings, glm::vec3(-7.0e4f, 9000.0f, 2.0e4f), 600.0);
    expectBackToFront("above the layer");
    settings.rings = 1;
    settings.ringDimension = 16;
    settings.maxLayers = 1;
    settings.particleDistance = 600.0f;
    generate(settings, glm::vec3(0.0f, 3000.0f, 0.0f), 0.0);
    EXPECT_LT(particleCount(), 256u);
    expectBackToFront("one partial block");
}

// The visibility pass (clouds/cull_particles.hlsl): below, inside and above the layer, and looking
// back along -z, the visible keys are the sorted keys whose bounding sphere is not wholly behind
// one of the view-projection's six planes (the CPU's test, in double precision), in the same
// order; every particle whose centre projects into the screen is among them; and many are culled.
TEST_F(CloudParticlesTest, TheVisibilityPassKeepsThoseInTheViewInOrder) {
    CloudSettings settings;
    settings.rings = 4;
    settings.ringDimension = 64;
    settings.particleDistance = 6.0e4f;
    const struct {
        glm::vec3 position;
        float yaw;
        const char* name;
    } views[] = {{{0.0f, 500.0f, 0.0f}, 0.0f, "below the layer"},
                 {{3.0e4f, 3000.0f, -1.0e4f}, 0.0f, "inside the layer"},
                 {{-7.0e4f, 9000.0f, 2.0e4f}, 0.0f, "above the layer"},
                 {{0.0f, 1500.0f, 0.0f}, 180.0f, "below, looking back"}};
    for (const auto& view : views) {
        camera.yawDegrees = view.yaw;
        generate(settings, view.position, 0.0);
        const unsigned count = particleCount();
        ASSERT_GT(count, 1000u) << view.name;
        const std::vector<glm::uvec2> keys = sortedKeys(count);
        const std::vector<gpu::CloudParticle> all = particles(clouds->capacity());
        ASSERT_NE(clouds->visibleArguments(), nullptr);
        const std::vector<unsigned> drawArguments = fromBytes<unsigned>(readBuffer(device(), context(), clouds->visibleArguments()), 8);
        const unsigned visible = drawArguments[3];
        EXPECT_EQ(drawArguments[4], 4u);
        EXPECT_EQ(drawArguments[5], visible);
        const std::vector<glm::uvec2> kept = fromBytes<glm::uvec2>(readBuffer(device(), context(), clouds->visibleKeys()), visible);

        const glm::dmat4 m(constants.viewProjection);
        const auto row = [&](int i) { return glm::dvec4(m[0][i], m[1][i], m[2][i], m[3][i]); };
        const glm::dvec4 planes[6] = {row(3) + row(0), row(3) - row(0), row(3) + row(1), row(3) - row(1), row(2), row(3) - row(2)};
        std::map<std::uint64_t, bool> keptKeys;
        for (const glm::uvec2& key : kept) keptKeys[(std::uint64_t(key.x) << 32) | key.y] = true;
        size_t borderline = 0, onScreen = 0, disagree = 0;
        for (const glm::uvec2& key : keys) {
            const gpu::CloudParticle& p = all[key.y];
            const double radius = std::max(p.centre.w, p.shape.x) * 1.01 + 1.0;
            const glm::dvec4 centre(glm::dvec3(glm::vec3(p.centre)), 1.0);
            bool inside = true, closeToPlane = false;
            for (const glm::dvec4& plane : planes) {
                const double scale = glm::length(glm::dvec3(plane));
                if (scale <= 0.0) continue;
                const double distance = glm::dot(plane, centre) / scale + radius;
                inside = inside && distance >= 0.0;
                closeToPlane = closeToPlane || std::abs(distance) < 1e-4 * radius + 0.5;
            }
            const bool isKept = keptKeys.count((std::uint64_t(key.x) << 32) | key.y) > 0;
            // Exactly the CPU's choice, but for particles within rounding of a plane.
            if (closeToPlane) ++borderline;
            else disagree += isKept != inside;
            const glm::dvec4 clip = m * centre;
            const bool centreOnScreen = clip.w > 0.0 && std::abs(clip.x) <= clip.w && std::abs(clip.y) <= clip.w && clip.z >= 0.0 && clip.z <= clip.w;
            onScreen += centreOnScreen;
            EXPECT_TRUE(!centreOnScreen || isKept) << view.name << ": a particle whose centre is on the screen was culled";
        }
        std::printf("%s: %u particles, %u drawn (%zu centres on the screen), %zu within rounding of a plane\n", view.name, count, visible, onScreen,
                    borderline);
        EXPECT_EQ(disagree, 0u) << view.name;
        EXPECT_EQ(keptKeys.size(), kept.size()) << view.name << ": a key kept twice";
        // In the back-to-front order of the sorted keys.
        std::map<std::uint64_t, size_t> position;
        for (size_t k = 0; k < keys.size(); ++k) position[(std::uint64_t(keys[k].x) << 32) | keys[k].y] = k;
        for (size_t k = 1; k < kept.size(); ++k)
            ASSERT_LT(position.at((std::uint64_t(kept[k - 1].x) << 32) | kept[k - 1].y), position.at((std::uint64_t(kept[k].x) << 32) | kept[k].y))
                << view.name << ": out of order at " << k;
        EXPECT_LT(visible, count * 3 / 4) << view.name << ": the view holds most of the field?";
    }
    camera.yawDegrees = 0.0f;
}

TEST_F(CloudParticlesTest, ParticlesAreFiniteOverPlacesAndEveryControlsExtremes) {
    std::vector<std::pair<std::string, CloudSettings>> cases;
    CloudSettings base;
    base.rings = 3;
    base.ringDimension = 32;
    cases.push_back({"base", base});
    auto with = [&](const char* name, auto change) {
        CloudSettings s = base;
        change(s);
        cases.push_back({name, s});
    };
    with("cloudiness 1", [](CloudSettings& s) { s.cloudiness = 1.0f; });
    with("altitude 1000, thickness 1500", [](CloudSettings& s) { s.altitude = 1000.0f; s.thickness = 1500.0f; });
    with("altitude 10000, thickness 100", [](CloudSettings& s) { s.altitude = 10000.0f; s.thickness = 100.0f; });
    with("speed 2", [](CloudSettings& s) { s.speed = 2.0f; });
    with("particle distance 1e4", [](CloudSettings& s) { s.particleDistance = 1.0e4f; });
    with("particle distance 5e5", [](CloudSettings& s) { s.particleDistance = 5.0e5f; });
    with("1 ring of 16", [](CloudSettings& s) { s.rings = 1; s.ringDimension = 16; });
    with("8 rings", [](CloudSettings& s) { s.rings = 8; });
    with("ring dimension 256", [](CloudSettings& s) { s.rings = 1; s.ringDimension = 256; });
    with("1 layer", [](CloudSettings& s) { s.maxLayers = 1; });
    with("16 layers", [](CloudSettings& s) { s.maxLayers = 16; });
    with("density map 128", [](CloudSettings& s) { s.densityResolution = 128; });
    with("density map 1024", [](CloudSettings& s) { s.densityResolution = 1024; });
    for (const auto& [name, settings] : cases)
        for (const float altitude : {100.0f, settings.altitude, 3.0e4f, 4.0e5f}) {
            generate(settings, glm::vec3(1.0e3f, altitude, -2.0e3f), 3600.0 * 5.0);
            const unsigned count = particleCount();
            if (std::abs(altitude - settings.altitude) < settings.particleDistance / 2.0f) {
                EXPECT_GT(count, 0u) << name << " at " << altitude << " m";
            }
            for (const gpu::CloudParticle& p : particles(count)) {
                const bool finite = std::isfinite(p.centre.x) && std::isfinite(p.centre.y) && std::isfinite(p.centre.z) &&
                                    std::isfinite(p.centre.w) && std::isfinite(p.shape.x) && std::isfinite(p.shape.y) && std::isfinite(p.shape.z);
                if (!finite || !(p.centre.w > 0.0f) || !(p.shape.x > 0.0f) || !(p.shape.y > 0.0f)) {
                    ADD_FAILURE() << name << " at " << altitude << " m: a particle is not finite and positive";
                    break;
                }
            }
        }
}

// Each particle's column along the sun (the optical depth nearer the sun, and beyond it) from the
// light-space tile lists against the CPU twin's walk over every particle (each crossing marched
// through the particle's density), with and without the early exit; the early exit changes the
// direct sunlight by less than 1e-6 and deck diffusion's light at the particle by at most 6%.
// The parts in the particle's deck (no clear air between them and the particle), which the GPU
// finds in one pass in the list's order, against the twin's union of the chords.
TEST_F(CloudParticlesTest, SunColumnsFromTheTileListsMatchACpuWalk) {
    const glm::vec3 position(0.0f, 1500.0f, 0.0f);
    DenseField field = denseField(0.8f, position);
    FrameContext frame = frameAt(position, 0.0);
    CloudSettings& dense = field.settings;
    const std::vector<ModelParticle>& model = field.model;
    ASSERT_FALSE(model.empty());
    const auto count = static_cast<unsigned>(model.size());
    const ParticleTablePrecomputation& tables = *field.tables;
    const ParticleTableParameters tableParameters;
    const glm::dvec3 toSun(sun.direction());

    std::vector<glm::vec4> columns[2];
    for (int earlyExit = 0; earlyExit < 2; ++earlyExit) {
        dense.opacityEarlyExit = earlyExit == 1;
        // The second frame's: the tile pool grows to what the first asked for.
        ParticleOpacity opacity(device());
        opacity.compute(frame, *clouds, tables.tables(), dense);
        const unsigned firstNodes = opacity.readCounts(device(), context()).nodes;
        opacity.compute(frame, *clouds, tables.tables(), dense);
        EXPECT_GE(opacity.nodeCapacity(), std::min(firstNodes, static_cast<unsigned>(ParticleOpacity::kMaxPoolBytes / 8)));
        columns[earlyExit] = fromBytes<glm::vec4>(readBuffer(device(), context(), opacity.sunColumnBuffer()), count);
        const ParticleOpacity::Counts counts = opacity.readCounts(device(), context());
        EXPECT_EQ(counts.nodesDropped, 0u);
        EXPECT_GT(counts.nodes, count);
        double worst = 0.0, sum = 0.0, deckWorst = 0.0, deckSum = 0.0;
        int shadowed = 0, under = 0, beyond = 0, deckBeyond = 0, parted = 0;
        // Optical depths compared through the light they leave: e^(-(1 - g^2) tau) and the slab's
        // 1 / (1 + 0.075 tau), each within [0, 1].
        const auto lightDifference = [](double got, double expected) {
            return std::max(std::abs(std::exp(-kScaledExtinctionShare * got) - std::exp(-kScaledExtinctionShare * expected)),
                            std::abs(1.0 / (1.0 + 0.075 * got) - 1.0 / (1.0 + 0.075 * expected)));
        };
        for (unsigned k = 0; k < count; ++k) {
            const SunColumn cpu = sunColumn(model, k, toSun, kEarthRadius, tableParameters.method, earlyExit ? kOpacityEarlyExitDepth : 0.0);
            const glm::dvec4 walked(columns[earlyExit][k]);
            const double difference = std::max(lightDifference(walked.x, cpu.above), lightDifference(walked.y, cpu.beyond));
            // The deck: its two parts, and the clouds nearer the sun past a gap.
            const double deck = std::max({lightDifference(walked.z, cpu.deckAbove), lightDifference(walked.w, cpu.deckBeyond),
                                          lightDifference(walked.x - walked.z, cpu.above - cpu.deckAbove)});
            if (!(difference < 0.05 && deck < 0.05) && beyond + deckBeyond < 5)
                std::printf("particle %u: GPU above %.4f beyond %.4f (deck %.4f, %.4f), CPU above %.4f beyond %.4f (deck %.4f, %.4f)\n", k, walked.x, walked.y,
                            walked.z, walked.w, cpu.above, cpu.beyond, cpu.deckAbove, cpu.deckBeyond);
            worst = std::max(worst, difference);
            sum += difference;
            beyond += difference > 0.05;
            deckWorst = std::max(deckWorst, deck);
            deckSum += deck;
            deckBeyond += deck > 0.05;
            shadowed += cpu.above > 5.0;
            under += cpu.beyond > 5.0;
            parted += cpu.above - cpu.deckAbove > 1.0 || cpu.beyond - cpu.deckBeyond > 1.0;
        }
        std::printf("early exit %s: %u particles, %d under more than 5 and %d over more than 5; |GPU - CPU| mean %.4f, worst %.4f, %d beyond 0.05\n",
                    earlyExit ? "on" : "off", count, shadowed, under, sum / count, worst, beyond);
        std::printf("  the deck: %d particles with more than 1 past a gap; |GPU - CPU| mean %.4f, worst %.4f, %d beyond 0.05\n",
                    parted, deckSum / count, deckWorst, deckBeyond);
        EXPECT_GT(shadowed, static_cast<int>(count / 10)) << "the test needs shadowed particles";
        EXPECT_GT(under, static_cast<int>(count / 10)) << "the test needs particles over others";
        EXPECT_GT(parted, static_cast<int>(count / 50)) << "the test needs decks with clouds past a gap";  // 95 of 3063
        EXPECT_LT(sum / count, 0.005);
        EXPECT_LE(beyond, static_cast<int>(count / 200));
        EXPECT_LT(deckSum / count, 0.005);
        EXPECT_LE(deckBeyond, static_cast<int>(count / 200));
    }
    // What the early exit changes: the direct sunlight, and deck diffusion's light at the particle
    // straight back towards the sun and straight on, relative to its light without the exit.
    double direct = 0.0, diffuse = 0.0;
    for (unsigned k = 0; k < count; ++k) {
        const glm::dvec4 full(columns[0][k]), cut(columns[1][k]);
        direct = std::max(direct, std::abs(std::exp(-kScaledExtinctionShare * cut.x) - std::exp(-kScaledExtinctionShare * full.x)));
        for (const double mu : {-1.0, 1.0}) {
            const double a = deckDiffuseRadiance(full.x, full.x + full.y, mu, 0.9), b = deckDiffuseRadiance(cut.x, cut.x + cut.y, mu, 0.9);
            if (a > 1e-3) diffuse = std::max(diffuse, std::abs(b / a - 1.0));
        }
    }
    std::printf("the early exit changes the direct sunlight by at most %.3g, deck diffusion's light by at most %.4f\n", direct, diffuse);
    EXPECT_LE(direct, 1e-6);
    EXPECT_LE(diffuse, 0.06);
}

// The clouds' shadow map (src/clouds/CloudShadowMap.h) read at points below, inside and above the
// layer (shadows/cloud_shadow.hlsli) against the CPU: the transmittance of every particle the
// point's ray to the sun crosses, exp(-sum of their optical depths), each chord marched through
// the particle's density (LightSpace.h's opticalDepthThrough). The map keeps one transmittance
// and one stretch per 39 m texel, so points within a texel of a particle's rim may differ by
// much; the bounds are on the mean and on the share of such points. Below the layer the map is
// exact up to that; inside it the density is taken as uniform along each texel's stretch, an
// approximation whose error the looser bounds state.
TEST_F(CloudParticlesTest, TheCloudShadowMapGivesEachPointTheParticlesTransmittanceTowardTheSun) {
    const glm::vec3 position(300.0f, 1500.0f, -200.0f);
    const DenseField field = denseField(0.6f, position);
    FrameContext frame = frameAt(position, 0.0);
    const CloudSettings& dense = field.settings;
    const std::vector<ModelParticle>& model = field.model;
    ASSERT_FALSE(model.empty());
    const ParticleTablePrecomputation& tables = *field.tables;
    const ParticleTableParameters tableParameters;
    CloudShadowMap map(device());
    map.render(frame, *clouds, tables.tables(), dense);
    ASSERT_TRUE(map.active());

    // Points on grids around the camera: on the ground below the layer (which spans 2650 to
    // 3350 m) within 12 km (the near map) and within 36 km (mostly the far map's), in the layer's
    // middle, and above it.
    const glm::dvec3 toSun(sun.direction());
    struct Level {
        const char* name;
        double height, spacing;
    };
    const Level levels[4] = {{"below the layer", 0.0, 1000.0},
                             {"below the layer, out to 36 km", 0.0, 3000.0},
                             {"in its middle", dense.altitude, 1000.0},
                             {"above it", dense.altitude + dense.thickness + 800.0, 1000.0}};
    constexpr int side = 24;
    std::vector<glm::vec4> queries;
    for (const Level& level : levels)
        for (int j = 0; j < side; ++j)
            for (int i = 0; i < side; ++i)
                queries.emplace_back(position.x + static_cast<float>((i - side / 2 + 0.37) * level.spacing), static_cast<float>(level.height),
                                     position.z + static_cast<float>((j - side / 2 + 0.61) * level.spacing), 0.0f);
    const auto count64 = static_cast<unsigned>(queries.size());
    const StructuredBuffer input = createStructuredBuffer(device(), count64, sizeof(glm::vec4), queries.data(), "cloud shadow queries");
    const StructuredBuffer output = createStructuredBuffer(device(), count64, sizeof(float), nullptr, "cloud shadow results");
    ConstantBuffer<gpu::CloudShadowConstants> shadowConstants(device());
    shadowConstants.update(context(), map.constants());
    context()->CSSetConstantBuffers(0, 1, shadowConstants.address());
    ID3D11ShaderResourceView* inputs[2] = {map.mapView(), input.srv.Get()};
    context()->CSSetShaderResources(0, 2, inputs);
    context()->CSSetUnorderedAccessViews(0, 1, output.uav.GetAddressOf(), nullptr);
    context()->CSSetShader(testShaderLibrary->computeShader({"clouds/cloud_shadow_probe.hlsl", "main", "cs_5_0", {}}), nullptr, 0);
    context()->Dispatch((count64 + 63) / 64, 1, 1);
    ID3D11UnorderedAccessView* noUav = nullptr;
    context()->CSSetUnorderedAccessViews(0, 1, &noUav, nullptr);
    const std::vector<float> fromMap = fromBytes<float>(readBuffer(device(), context(), output.buffer.Get()), count64);

    for (int level = 0; level < 4; ++level) {
        const char* name = levels[level].name;
        double sum = 0.0;
        int shadowed = 0, lit = 0, beyond = 0;
        for (int k = level * side * side; k < (level + 1) * side * side; ++k) {
            const glm::dvec3 point(queries[k]);
            double opticalDepth = 0.0;
            for (const ModelParticle& q : model) opticalDepth += opticalDepthThrough(q, point, toSun, kEarthRadius, tableParameters.method);
            const double cpu = std::exp(-opticalDepth);
            const double difference = std::abs(fromMap[k] - cpu);
            sum += difference;
            beyond += difference > 0.25;
            shadowed += cpu < 0.5;
            lit += cpu > 0.95;
            if (difference > 0.25 && beyond <= 3) std::printf("  %s, point %.0f %.0f: map %.4f, particles %.4f\n", name, point.x, point.z, fromMap[k], cpu);
        }
        const int points = side * side;
        std::printf("%s: %d points, %d shadowed below 0.5, %d lit above 0.95; |map - particles| mean %.4f, %d beyond 0.25\n", name, points,
                    shadowed, lit, sum / points, beyond);
        if (level == 3) {
            EXPECT_EQ(shadowed, 0) << "nothing is above the layer";
            EXPECT_LT(sum / points, 1e-3);
            continue;
        }
        if (level < 2) {
            // (The particles end 20 km out.)
            EXPECT_GT(shadowed, points / (level == 0 ? 5 : 10)) << "the test needs shadowed points";
            EXPECT_GT(lit, points / 10) << "the test needs points in the sun";
        }
        // Measured: below, 0.003 and none beyond; in the middle, 0.065 and 8% beyond.
        EXPECT_LT(sum / points, level < 2 ? 0.01 : 0.08) << name;
        EXPECT_LE(beyond, points / (level < 2 ? 50 : 10)) << name;
    }
}

}  // namespace
}  // namespace firmament::test

namespace firmament::test {
namespace {

// Runs an entry of the reference's test kernel (tests/shaders/clouds/trace_rays.hlsl) over
// `count` rays (origin, direction: 32 bytes each) with `constants`; one float4 per ray back.
std::vector<glm::vec4> runReferenceKernel(ID3D11Device* device, ID3D11DeviceContext* context, ShaderLibrary& shaders, CloudReference& reference,
                                          CloudParticles& particles, ID3D11Buffer* frameConstants, const char* entry,
                                          const gpu::CloudReferenceConstants& constants, const void* rays, unsigned count) {
    const StructuredBuffer input = createStructuredBuffer(device, count, 32, rays, "test rays");
    const StructuredBuffer results = createStructuredBuffer(device, count, 16, nullptr, "test results");
    reference.setConstants(context, constants);
    ID3D11Buffer* buffers[] = {frameConstants, particles.fieldConstants()};
    context->CSSetConstantBuffers(0, 2, buffers);
    reference.bindMedium(context, particles);
    context->CSSetShaderResources(0, 1, input.srv.GetAddressOf());
    context->CSSetUnorderedAccessViews(0, 1, results.uav.GetAddressOf(), nullptr);
    context->CSSetShader(shaders.computeShader({"clouds/trace_rays.hlsl", entry, "cs_5_0", {}}), nullptr, 0);
    context->Dispatch(groupCount(count, 64), 1, 1);
    ID3D11UnorderedAccessView* noView = nullptr;
    context->CSSetUnorderedAccessViews(0, 1, &noView, nullptr);
    ID3D11ShaderResourceView* none[13] = {};
    context->CSSetShaderResources(0, 13, none);
    return fromBytes<glm::vec4>(readBuffer(device, context, results.buffer.Get()), count);
}

// The medium the GPU reference walks (clouds/reference_medium.hlsli: the particles found through
// the cloud grid's rings) against the CPU twin's (ParticleMedium: a uniform grid of its own) at
// points in and around the particles, and the walk's majorant against the extinction it bounds.
TEST_F(CloudParticlesTest, TheGpuReferencesMediumIsTheParticlesSummedDensity) {
    const glm::vec3 position(0.0f, 1500.0f, 0.0f);
    DenseField field = denseField(0.6f, position);
    ASSERT_FALSE(field.model.empty());
    FrameContext frame = frameAt(position, 0.0);
    CloudReference reference(device());
    reference.buildIndex(frame, *clouds, field.settings);
    // Points about particles, out to 1.3 times their radius, where neighbouring cells' particles reach.
    struct Point {
        glm::vec4 origin, direction;
    };
    std::vector<Point> points;
    std::mt19937 pick(5);
    std::uniform_real_distribution<float> unit(-1.0f, 1.0f);
    for (size_t k = 0; k < 4096; ++k) {
        const ModelParticle& q = field.model[(k * 7919u) % field.model.size()];
        const glm::vec3 offset(unit(pick) * 1.3f * q.horizontalRadius, unit(pick) * 1.3f * q.verticalRadius, unit(pick) * 1.3f * q.horizontalRadius);
        const glm::vec3 direction = glm::normalize(glm::vec3(unit(pick), unit(pick), unit(pick)) + glm::vec3(0.0f, 0.0f, 1e-3f));
        points.push_back({glm::vec4(q.centre + offset, 0.0f), glm::vec4(direction, 0.0f)});
    }
    const auto count = static_cast<unsigned>(points.size());
    gpu::CloudReferenceConstants c{};
    c.paths = glm::uvec4(0u, 0u, 0u, count);
    c.options = glm::uvec4(static_cast<unsigned>(field.settings.particleDensity), 0u, kReferenceEventLimit, 0u);
    const std::vector<glm::vec4> gpuResults =
        runReferenceKernel(device(), context(), *testShaderLibrary, reference, *clouds, frameConstants->get(), "extinction_at", c, points.data(), count);

    const ParticleMedium medium(field.model, kEarthRadius, field.settings.particleDensity, 0.07);
    int inCloud = 0, overlapping = 0, wrong = 0, unbounded = 0;
    for (unsigned k = 0; k < count; ++k) {
        const glm::dvec3 p(points[k].origin);
        const double cpu = medium.extinction(p), gpuExtinction = gpuResults[k].x, majorant = gpuResults[k].y;
        inCloud += cpu > 0.0;
        int reaching = 0;
        for (const ModelParticle& q : field.model) reaching += glm::length(glm::dvec3(q.centre) - p) < std::max(q.horizontalRadius, q.verticalRadius);
        overlapping += reaching > 1 && cpu > 0.0;
        const bool differs = !(std::abs(gpuExtinction - cpu) <= 1e-4 * 0.07 + 1e-3 * cpu);
        wrong += differs;
        unbounded += gpuExtinction > majorant * 1.0001;
        if ((differs || gpuExtinction > majorant * 1.0001) && wrong + unbounded <= 5)
            std::printf("point %u: GPU %.6f (majorant %.6f), CPU %.6f\n", k, gpuExtinction, majorant, cpu);
    }
    std::printf("%u points: %d in a cloud, %d where particles overlap; %d differ, %d above the majorant\n", count, inCloud, overlapping, wrong, unbounded);
    EXPECT_GT(inCloud, static_cast<int>(count / 4)) << "the test needs points in the clouds";
    EXPECT_GT(overlapping, static_cast<int>(count / 20)) << "the test needs points where particles overlap";
    EXPECT_EQ(wrong, 0);
    EXPECT_EQ(unbounded, 0);
}

// The path-traced reference on the GPU (clouds/reference_paths.hlsli through the index of
// clouds/reference_index.hlsl) against its CPU twin (CloudPathTracer over a ParticleMedium, with
// a uniform grid of its own) on the same particles and rays, under the same lighting: a white
// sun, a grey sky and, for half of the rays, a Lambertian ground. The two share no code, so a
// fault in either index, walk, tracker or path shows as a difference beyond the Monte Carlo
// noise. Each ray's estimates are compared by their standard errors (at most two of 192 beyond 4
// sigma); the means over the rays within 4 of their standard errors, or 3% where that is less.
TEST_F(CloudParticlesTest, TheGpuReferenceMatchesTheCpuPathTracerOnTheSameParticles) {
    const glm::vec3 position(0.0f, 1500.0f, 0.0f);
    DenseField field = denseField(0.6f, position);
    ASSERT_FALSE(field.model.empty());
    FrameContext frame = frameAt(position, 0.0);
    CloudReference reference(device());
    reference.buildIndex(frame, *clouds, field.settings);

    // 96 rays up into the layer from below, 96 down into it from above (spread over the field).
    struct Ray {
        glm::vec4 origin, direction;
    };
    std::vector<Ray> rays;
    std::mt19937 pick(7);
    std::uniform_real_distribution<float> unit(0.0f, 1.0f);
    for (int k = 0; k < 192; ++k) {
        const bool above = k >= 96;
        const float azimuth = 6.2831853f * unit(pick), elevation = 0.15f + 1.2f * unit(pick);
        glm::vec3 direction(std::cos(elevation) * std::cos(azimuth), std::sin(elevation), std::cos(elevation) * std::sin(azimuth));
        glm::vec3 origin = position + glm::vec3((unit(pick) - 0.5f) * 6000.0f, 0.0f, (unit(pick) - 0.5f) * 6000.0f);
        if (above) {
            direction.y = -direction.y;
            origin.y = 5200.0f;
        }
        rays.push_back({glm::vec4(origin, 0.0f), glm::vec4(direction, 0.0f)});
    }
    const auto count = static_cast<unsigned>(rays.size());
    constexpr unsigned kPaths = 48;
    const glm::vec3 sunIrradiance(1.0f);
    constexpr float kSky = 0.1f, kGroundHeight = 0.0f;
    const glm::vec3 albedo(0.3f, 0.3f, 0.3f);

    std::vector<glm::vec4> gpuResults[2];
    for (int ground = 0; ground < 2; ++ground) {
        gpu::CloudReferenceConstants c{};
        c.paths = glm::uvec4(0u, kPaths, 977u + ground, count);
        c.options = glm::uvec4(static_cast<unsigned>(field.settings.particleDensity), static_cast<unsigned>(ground), kReferenceEventLimit, 0u);
        c.light = glm::vec4(sunIrradiance, kSky);
        c.ground = glm::vec4(kGroundHeight, albedo);
        gpuResults[ground] =
            runReferenceKernel(device(), context(), *testShaderLibrary, reference, *clouds, frameConstants->get(), "main", c, rays.data(), count);
    }

    const ParticleMedium medium(field.model, kEarthRadius, field.settings.particleDensity, 0.07);
    std::mt19937_64 random(11);
    for (int ground = 0; ground < 2; ++ground) {
        CloudLighting lighting;
        lighting.toSun = glm::dvec3(sun.direction());
        lighting.sunIrradiance = glm::dvec3(sunIrradiance);
        lighting.sky = [](glm::dvec3) { return glm::dvec3(kSky); };
        if (ground) {
            lighting.groundHeight = kGroundHeight;
            lighting.groundAlbedo = glm::dvec3(albedo);
        }
        const CloudPathTracer tracer(medium, lighting, {});
        int beyond = 0, lit = 0;
        double gpuSum = 0.0, cpuSum = 0.0, variance = 0.0, worst = 0.0;
        for (unsigned k = 0; k < count; ++k) {
            const MediumRay ray{glm::dvec3(rays[k].origin), glm::dvec3(rays[k].direction)};
            double sum = 0.0, squares = 0.0;
            for (unsigned n = 0; n < kPaths; ++n) {
                const glm::dvec3 l = tracer.radiance(ray, random);
                const double grey = (l.x + l.y + l.z) / 3.0;
                sum += grey;
                squares += grey * grey;
            }
            const double cpu = sum / kPaths, cpuError2 = std::max(squares / kPaths - cpu * cpu, 0.0) / kPaths;
            const glm::vec4 g = gpuResults[ground][k];
            const double gpuGrey = (g.x + g.y + g.z) / 3.0, gpuError2 = static_cast<double>(g.w) * g.w;
            const double sigma = std::sqrt(cpuError2 + gpuError2 + 1e-12);
            const double z = std::abs(gpuGrey - cpu) / sigma;
            worst = std::max(worst, z);
            beyond += z > 4.0;
            lit += cpu > 1.5 * kSky;
            gpuSum += gpuGrey;
            cpuSum += cpu;
            variance += cpuError2 + gpuError2;
            if (z > 4.0 && beyond <= 5)
                std::printf("ray %u: GPU %.4f +- %.4f, CPU %.4f +- %.4f\n", k, gpuGrey, std::sqrt(gpuError2), cpu, std::sqrt(cpuError2));
        }
        const double meanSigma = std::sqrt(variance) / count;
        std::printf("ground %s: %u rays of %u paths, %d lit by the clouds; mean GPU %.4f, CPU %.4f (+- %.4f); worst %.1f sigma, %d beyond 4\n",
                    ground ? "on" : "off", count, kPaths, lit, gpuSum / count, cpuSum / count, meanSigma, worst, beyond);
        EXPECT_GT(lit, static_cast<int>(count / 4)) << "the test needs rays that meet clouds";
        EXPECT_LE(beyond, 2);
        EXPECT_LT(std::abs(gpuSum - cpuSum) / count, std::max(4.0 * meanSigma, 0.03 * cpuSum / count));
    }
}

}  // namespace
}  // namespace firmament::test
