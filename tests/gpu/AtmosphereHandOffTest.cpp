// The atmosphere as a service to other techniques, on the WARP device: ScatteringLookup hands
// over Yusov's tables with their constants and sampler, so that the look-up functions a second
// technique runs on them give exactly what they give on the pre-computation's own tables; and
// GroundLighting gives the ground one region per model drawn, with the columns each lights.
#include "AtmosphereQueries.h"
#include "FrameTest.h"
#include "atmosphere/Atmosphere.h"
#include "atmosphere/SunDisc.h"
#include "core/Camera.h"
#include "gpu/CommonStates.h"

#include <gtest/gtest.h>

#include <cmath>
#include <memory>

namespace firmament::test {
namespace {

constexpr int kWidth = 64, kHeight = 32;

class AtmosphereHandOff : public FrameTest {
protected:
    void SetUp() override {
        FrameTest::SetUp();
        setUpFrame(kWidth, kHeight);
    }

    // A frame context whose work finishes at once; nothing is drawn with it here.
    FrameContext frame() {
        return frameContext(constants, camera, sun);
    }

    // Small tables, single scattering only: the hand-offs, not the tables, are under test.
    static AtmosphereSettings smallTables() {
        AtmosphereSettings s;
        s.resolution = LutResolution::Small;
        s.scatteringOrders = 1;
        return s;
    }

    gpu::FrameConstants constants{};
    Camera camera;
    Sun sun;
};

TEST_F(AtmosphereHandOff, ScatteringLookupGivesYusovsTablesAsThePrecomputationHasThem) {
    Atmosphere atmosphere(device(), TableStorage{});
    AtmosphereSettings settings = smallTables();
    settings.scatteringOrders = 2;  // so that no two of the 4D tables are equal
    settings.singleScattering = SingleScatteringMode::Integration;
    settings.multipleScattering = MultipleScatteringMode::Occluded;
    settings.integrationSteps = 17;
    FrameContext f = frame();
    EXPECT_FALSE(atmosphere.scatteringLookup(f, settings).ready) << "no tables before the first update";
    atmosphere.update(f, settings);
    const ScatteringLookup lookup = atmosphere.scatteringLookup(f, settings);
    ASSERT_TRUE(lookup.ready);
    for (const void* p : {static_cast<const void*>(lookup.atmosphere), static_cast<const void*>(lookup.netDensity),
                          static_cast<const void*>(lookup.singleScattering), static_cast<const void*>(lookup.highOrderScattering),
                          static_cast<const void*>(lookup.multipleScattering), static_cast<const void*>(lookup.ambientLight),
                          static_cast<const void*>(lookup.linearClamp)})
        EXPECT_NE(p, nullptr);
    EXPECT_EQ(lookup.singleMode, SingleScatteringMode::Integration);
    EXPECT_EQ(lookup.multipleMode, MultipleScatteringMode::Occluded);
    EXPECT_EQ(lookup.integrationSteps, 17);
    EXPECT_FLOAT_EQ(lookup.sunCosAngularRadius, static_cast<float>(std::cos(kSunAngularRadius)));
    EXPECT_FLOAT_EQ(lookup.sunDiscRadiance, static_cast<float>(sunDiscRadiance()));

    // The reference: the same tables computed here, read with their own constants.
    const AtmosphereParameters p = AtmosphereParameters::from(settings);
    YusovPrecomputation own(device(), p);
    own.runAll(context(), *productShaderLibrary);
    ConstantBuffer<gpu::AtmosphereConstants> ownConstants(device());
    ownConstants.update(context(), p.constants());
    const auto sampler = states::linearClamp(device());
    const std::vector<Query> sky = randomSkyQueries(p, 256, 11, 2.0).queries;
    const std::vector<Query> sunward = randomSunQueries(p, 256, 12);
    const ShaderKey scattering{"atmosphere/lookup_probe.hlsl", "scattering", "cs_5_0", {}};
    const ShaderKey transmittance{"atmosphere/lookup_probe.hlsl", "transmittance", "cs_5_0", {}};
    const auto handedOver = runProbe(scattering, sky, {lookup.atmosphere}, {lookup.netDensity, lookup.singleScattering}, lookup.linearClamp);
    const auto expected = runProbe(scattering, sky, {ownConstants.get()}, {own.tables().netDensity.srv.Get(), own.tables().singleScattering.srv.Get()},
                                   sampler.Get());
    const auto handedOverSun = runProbe(transmittance, sunward, {lookup.atmosphere}, {lookup.netDensity, lookup.singleScattering}, lookup.linearClamp);
    const auto expectedSun = runProbe(transmittance, sunward, {ownConstants.get()},
                                      {own.tables().netDensity.srv.Get(), own.tables().singleScattering.srv.Get()}, sampler.Get());
    int nonZero = 0;
    for (size_t i = 0; i < sky.size(); ++i) {
        EXPECT_EQ(handedOver[i], expected[i]) << "sky query " << i;
        EXPECT_EQ(handedOverSun[i], expectedSun[i]) << "sun query " << i;
        nonZero += handedOver[i].r > 0.0f;
    }
    EXPECT_GT(nonZero, 200) << "the look-ups read light";
}

TEST_F(AtmosphereHandOff, GroundLightingGivesOneRegionPerModelDrawn) {
    Atmosphere atmosphere(device(), TableStorage{});
    FrameContext f = frame();
    struct Case {
        AtmosphereModel model;
        ModelComparison comparison;
        AtmosphereModel compared;
        std::vector<GroundLightingModel> models;
        std::vector<glm::ivec2> columns;  // [first, end), the end clipped to the frame's width
    };
    using M = AtmosphereModel;
    using G = GroundLightingModel;
    const Case cases[] = {
        {M::Yusov2013, ModelComparison::None, M::Bruneton2008, {G::Yusov2013}, {{0, kWidth}}},
        {M::Bruneton2008, ModelComparison::None, M::Bruneton2008, {G::Bruneton2008}, {{0, kWidth}}},
        {M::Hillaire2020, ModelComparison::None, M::Bruneton2008, {G::Hillaire2020}, {{0, kWidth}}},
        {M::Yusov2013, ModelComparison::Split, M::Bruneton2008, {G::Yusov2013, G::Bruneton2008}, {{0, kWidth / 2}, {kWidth / 2, kWidth}}},
        {M::Hillaire2020, ModelComparison::Split, M::Yusov2013, {G::Hillaire2020, G::Yusov2013}, {{0, kWidth / 2}, {kWidth / 2, kWidth}}},
        {M::Yusov2013, ModelComparison::Difference, M::Hillaire2020, {G::Yusov2013}, {{0, kWidth}}},
        {M::Bruneton2008, ModelComparison::ThreeWay, M::Bruneton2008, {G::Yusov2013, G::Bruneton2008, G::Hillaire2020},
         {{0, kWidth / 3}, {kWidth / 3, 2 * kWidth / 3}, {2 * kWidth / 3, kWidth}}},
    };
    for (const Case& c : cases) {
        AtmosphereSettings s = smallTables();
        s.model = c.model;
        s.comparison = c.comparison;
        s.comparedModel = c.compared;
        atmosphere.update(f, s);
        const std::vector<GroundLighting> regions = atmosphere.groundLighting(f, s);
        ASSERT_EQ(regions.size(), c.models.size()) << static_cast<int>(c.model) << " " << static_cast<int>(c.comparison);
        for (size_t i = 0; i < regions.size(); ++i) {
            const GroundLighting& g = regions[i];
            EXPECT_EQ(g.model, c.models[i]);
            EXPECT_EQ(glm::ivec2(g.firstColumn, std::min(g.endColumn, kWidth)), c.columns[i]) << "region " << i;
            EXPECT_NE(g.atmosphere, nullptr);
            EXPECT_NE(g.sunTransmittance, nullptr);
            EXPECT_NE(g.skyIrradiance, nullptr);
            EXPECT_EQ(g.modelConstants != nullptr, g.model != GroundLightingModel::Yusov2013);
        }
    }
    // Scattering off: the ground's own stand-in, over the whole frame.
    AtmosphereSettings off = smallTables();
    off.enabled = false;
    const std::vector<GroundLighting> none = atmosphere.groundLighting(f, off);
    ASSERT_EQ(none.size(), 1u);
    EXPECT_EQ(none[0].model, GroundLightingModel::None);
    EXPECT_EQ(none[0].firstColumn, 0);
    EXPECT_GE(none[0].endColumn, kWidth);
}

}  // namespace
}  // namespace firmament::test
