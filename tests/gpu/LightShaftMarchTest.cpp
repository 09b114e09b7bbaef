// The light shafts' ray march (shaders/lightshafts/ray_march.hlsli) on the WARP device, against
// a CPU computation with a known occluder: the shadow test's horizontal square hovering 45 m
// over flat ground, drawn into the cascades. Along rays from a camera above it and from one in
// its shadow, the lit length D_lit and the distance to the first lit point D_start must equal
// the geometry's (the ray's part under the square whose way to the sun meets the square), and
// the in-scattering integrated over the lit steps must equal the reference atmosphere's
// integral over the lit parts of the ray. Two set-ups: four cascades reaching 1 km marched from
// cascade 0, and the defaults (four cascades reaching 100 km, marched from cascade 1, whose split
// lies 1.3 km away: the square and every ray lie nearer than it).
#include "KnownOccluder.h"
#include "FrameTest.h"
#include "atmosphere/Atmosphere.h"
#include "atmosphere/AtmosphereParameters.h"
#include "atmosphere/ReferenceAtmosphere.h"
#include "core/Camera.h"
#include "gpu/CommonStates.h"
#include "lightshafts/LightShafts.h"
#include "shadows/CascadedShadowMaps.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <memory>

namespace firmament::test {
namespace {

struct RayQuery {
    glm::vec4 a, b;  // a: view direction, ray length; b: unused
};

struct ProbeConstants {
    glm::vec4 camera, toSun;
};

constexpr double kMaxRayLength = 800.0;

// The sun of every case: 35 degrees up.
Sun testSun() {
    Sun sun;
    sun.elevationDegrees = 35.0f;
    sun.azimuthDegrees = -30.0f;
    return sun;
}

// The part [first, second] of the ray C + s v, s in [0, length], in the square's shadow: below
// the square, with the way to the sun crossing the square's height inside it. Empty when
// first >= second.
glm::dvec2 shadowInterval(glm::dvec3 c, glm::dvec3 v, double length, glm::dvec3 toSun) {
    double lower = 0.0, upper = length;
    const double h = kSquareHeight;
    if (v.y > 0.0) upper = std::min(upper, (h - c.y) / v.y);
    else if (v.y < 0.0) lower = std::max(lower, (h - c.y) / v.y);
    else if (c.y >= h) return {0.0, 0.0};
    // Where the way to the sun from C + s v meets y = h: a + b s.
    const glm::dvec3 a = c + toSun * ((h - c.y) / toSun.y);
    const glm::dvec3 b = v - toSun * (v.y / toSun.y);
    const auto clip = [&](double origin, double slope, double lo, double hi) {
        if (std::abs(slope) < 1e-12) {
            if (origin < lo || origin > hi) upper = lower;
            return;
        }
        double s0 = (lo - origin) / slope, s1 = (hi - origin) / slope;
        if (s0 > s1) std::swap(s0, s1);
        lower = std::max(lower, s0);
        upper = std::min(upper, s1);
    };
    clip(a.x, b.x, kSquare.x, kSquare.z);
    clip(a.z, b.z, kSquare.y, kSquare.w);
    return {lower, std::max(upper, lower)};
}

class LightShaftMarch : public FrameTest {
protected:
    void SetUp() override {
        FrameTest::SetUp();
        setUpFrame(64, 32);
    }

    struct Case {
        const char* label;
        Camera camera;
        bool cameraInShadow;
        ShadowSettings shadows;
        int firstCascade;
    };

    // The cascades' set-ups: four reaching 1 km marched from cascade 0, or the defaults.
    static ShadowSettings nearCascades() {
        ShadowSettings s;
        s.cascades = 4;
        s.distanceKm = 1.0f;
        return s;
    }

    void check(const Case& c) {
        const Sun sun = testSun();
        const glm::dvec3 toSun = glm::dvec3(sun.direction());
        CascadedShadowMaps shadows(device());
        shadows.update(context(), c.camera, 16.0 / 9.0, toSun, c.shadows, 2000.0, c.firstCascade);
        drawKnownOccluder(device(), context(), *testShaderLibrary, shadows);

        // Small tables: the march, not the tables, is under test; single scattering integrated.
        AtmosphereSettings atmosphereSettings;
        atmosphereSettings.resolution = LutResolution::Small;
        atmosphereSettings.scatteringOrders = 1;
        atmosphereSettings.singleScattering = SingleScatteringMode::Integration;
        atmosphereSettings.multipleScattering = MultipleScatteringMode::None;
        Atmosphere atmosphere(device(), TableStorage{});
        gpu::FrameConstants constants{};
        FrameContext frame{device(), context(), *productShaderLibrary, *profiler, targets, frameConstants->get(), constants, c.camera, sun,
                           0.0, 1.0 / 60.0, true};
        atmosphere.update(frame, atmosphereSettings);
        const ScatteringLookup lookup = atmosphere.scatteringLookup(frame, atmosphereSettings);
        ASSERT_TRUE(lookup.ready);
        LightShaftSettings shaftSettings;
        shaftSettings.firstCascade = c.firstCascade;
        ConstantBuffer<gpu::LightShaftConstants> shaftConstants(device());
        shaftConstants.update(context(), LightShafts::constants(shaftSettings, lookup, shadows.inputs().resolution));
        ConstantBuffer<ProbeConstants> probe(device());
        probe.update(context(), ProbeConstants{glm::vec4(c.camera.position, 1.0f), glm::vec4(glm::vec3(toSun), 0.0f)});

        // Rays through a grid of the camera's view, to the ground or kMaxRayLength.
        const glm::mat4 toWorld = glm::inverse(c.camera.projection(16.0f / 9.0f) * c.camera.view());
        const glm::dvec3 camera(c.camera.position);
        std::vector<RayQuery> queries;
        for (int y = 0; y < 18; ++y)
            for (int x = 0; x < 32; ++x) {
                const glm::vec4 farPoint = toWorld * glm::vec4((x + 0.5f) / 32.0f * 2.0f - 1.0f, 1.0f - (y + 0.5f) / 18.0f * 2.0f, 0.5f, 1.0f);
                const glm::dvec3 v = glm::normalize(glm::dvec3(farPoint) / static_cast<double>(farPoint.w) - camera);
                const double length = v.y < 0.0 ? std::min(-camera.y / v.y, kMaxRayLength) : kMaxRayLength;
                queries.push_back({glm::vec4(glm::vec3(v), static_cast<float>(length)), glm::vec4(0.0f)});
            }
        const ShadowInputs inputs = shadows.inputs();
        context()->CSSetSamplers(1, 1, &inputs.comparison);
        const std::initializer_list<ID3D11ShaderResourceView*> tables{lookup.netDensity, lookup.singleScattering, lookup.highOrderScattering,
                                                                       lookup.multipleScattering, inputs.map};
        const auto marched = runProbe({"lightshafts/march_probe.hlsl", "march", "cs_5_0", {}}, queries,
                                      {lookup.atmosphere, shaftConstants.get(), inputs.constants, probe.get()}, tables, lookup.linearClamp);
        const auto scattered = runProbe({"lightshafts/march_probe.hlsl", "inscattering", "cs_5_0", {}}, queries,
                                        {lookup.atmosphere, shaftConstants.get(), inputs.constants, probe.get()}, tables, lookup.linearClamp);

        const AtmosphereParameters p = AtmosphereParameters::from(atmosphereSettings);
        const atmosphere::ReferenceAtmosphere reference(p);
        const glm::dvec3 earthCentre(0.0, -p.earthRadius, 0.0);
        const std::vector<Cascade>& cascades = shadows.cascades();
        const glm::dvec3 forward = glm::normalize(glm::dvec3(c.camera.forward()));
        int crossing = 0, worstRay = -1;
        double worstLit = 0.0, worstScattering = 0.0;
        for (size_t i = 0; i < queries.size(); ++i) {
            const glm::dvec3 v(queries[i].a);
            const double length = queries[i].a.w;
            const glm::dvec2 shadow = shadowInterval(camera, v, length, toSun);
            // The coarsest cascade the march crosses: the one holding the ray's end, or the first marched.
            size_t coarsest = static_cast<size_t>(c.firstCascade);
            while (coarsest + 1 < cascades.size() && length * glm::dot(v, forward) > cascades[coarsest].farDepth) ++coarsest;
            const double texel = cascades[coarsest].texelWorldSize;
            const double shadowed = shadow.y - shadow.x;
            crossing += shadowed > 1.0;
            // One march step is a texel of the coarsest cascade crossed at most, along the ray: its
            // length across the sun's direction. Two edges, each off by a step and the filter's
            // half texel. Where the ray enters the shadow under the square, the casters'
            // slope-scaled bias (2 texels of the square's depth slope, cot(elevation) per texel)
            // lets it stay lit while its depth below the square grows, at |v.y| / sin(elevation)
            // per metre.
            const double across = std::max(glm::length(v - toSun * glm::dot(v, toSun)), 0.05);
            const double cosElevation = std::sqrt(1.0 - toSun.y * toSun.y);
            const double tolerance = texel * (3.0 / across + 2.5 * cosElevation / std::max(std::abs(v.y), 0.05)) + 0.05;
            const glm::vec4 m = marched[i];
            const double litLength = m.x + m.z + (length - m.w);  // the stretches not marched are lit
            const double litError = std::abs(litLength - (length - shadowed));
            EXPECT_LT(litError, tolerance) << c.label << ", ray " << i << ": lit " << litLength << " m, expected " << length - shadowed << " m";
            if (litError > worstLit) {
                worstLit = litError;
                worstRay = static_cast<int>(i);
            }
            if (c.cameraInShadow && shadow.x <= 0.0 && shadowed > 1.0 && shadow.y < length) {
                EXPECT_NEAR(m.y, shadow.y, tolerance) << c.label << ", ray " << i << ": the first lit point";
            }

            // Single scattering over the lit parts, [0, first] and [second, length].
            const glm::dvec3 start = camera - earthCentre;
            const double cosTheta = glm::dot(v, toSun);
            const auto integrand = [&](double s) {
                const glm::dvec3 point = start + v * s;
                const glm::dvec3 rho = reference.density(glm::length(point) - p.earthRadius);
                const glm::dvec3 toCamera = glm::exp(-reference.opticalDepth(reference.netDensity(start, point)));
                const glm::dvec3 beta = p.rayleighScattering * rho.x * atmosphere::rayleighPhase(cosTheta) +
                                        p.mieScattering * rho.y * atmosphere::miePhase(cosTheta, p.mieAsymmetry);
                return beta * toCamera * reference.sunTransmittance(point, toSun);
            };
            glm::dvec3 expected(0.0);
            if (shadowed > 0.0) {
                expected += atmosphere::gaussLegendre3(integrand, 0.0, shadow.x, 4);
                expected += atmosphere::gaussLegendre3(integrand, shadow.y, length, 4);
            } else {
                expected += atmosphere::gaussLegendre3(integrand, 0.0, length, 4);
            }
            // The error the lit length allows, at this ray's integrand, plus 2% (the tables'
            // sun transmittance and float sums).
            const double allowed = 0.02 * expected.b + tolerance * integrand(0.0).b;
            const double error = std::abs(scattered[i].b - expected.b);
            EXPECT_LT(error, allowed) << c.label << ", ray " << i << ": in-scattering " << scattered[i].b << ", expected " << expected.b;
            worstScattering = std::max(worstScattering, error / allowed);
        }
        std::printf("%s: %zu rays, %d through the shadow; largest lit-length error %.3f m (ray %d); largest in-scattering error %.2f of its allowance\n", c.label,
                    queries.size(), crossing, worstLit, worstRay, worstScattering);
        EXPECT_GT(crossing, 60) << c.label << ": too few rays cross the shadow to test it";
    }

};

// A camera above the square, looking down across it.
Camera cameraAboveTheSquare() {
    Camera above;
    above.position = {10.0f, 150.0f, -100.0f};
    above.yawDegrees = 5.0f;
    above.pitchDegrees = -25.0f;
    return above;
}

// A camera 20 m up where the way to the sun meets the square's middle, looking across the
// shadow: its rays start in shadow and leave it.
Camera cameraInTheShadow() {
    const glm::dvec3 toSun = glm::dvec3(testSun().direction());
    const glm::dvec3 middle(0.5 * (kSquare.x + kSquare.z), kSquareHeight, 0.5 * (kSquare.y + kSquare.w));
    Camera inShadow;
    inShadow.position = glm::vec3(middle - toSun * ((kSquareHeight - 20.0) / toSun.y));
    inShadow.yawDegrees = 60.0f;
    inShadow.pitchDegrees = -5.0f;
    return inShadow;
}

TEST_F(LightShaftMarch, LitLengthAndInscatteringMatchTheOccludersGeometry) {
    check({"camera above the square", cameraAboveTheSquare(), false, nearCascades(), 0});
    check({"camera in the shadow", cameraInTheShadow(), true, nearCascades(), 0});
}

// At the defaults the first cascade marched is 1, whose split lies about 1.3 km away: the
// square and the rays (800 m at most) all lie nearer. The march must still see the square's
// shadow (it used to count everything before split 1 as lit).
TEST_F(LightShaftMarch, ACasterNearerThanTheFirstMarchedSplitShadowsTheHazeAtTheDefaults) {
    const LightShaftSettings defaults;
    const ShadowSettings shadowDefaults;
    ASSERT_EQ(defaults.firstCascade, 1);
    const std::vector<double> splits = cascadeSplits(Camera{}.nearPlane, shadowDefaults.distanceKm * 1000.0, shadowDefaults.cascades,
                                                     shadowDefaults.partitioningFactor);
    ASSERT_GT(splits[1], kMaxRayLength + 400.0) << "the test needs the square and its rays nearer than split 1";
    check({"defaults, camera above the square", cameraAboveTheSquare(), false, shadowDefaults, defaults.firstCascade});
    check({"defaults, camera in the shadow", cameraInTheShadow(), true, shadowDefaults, defaults.firstCascade});
}

}  // namespace
}  // namespace firmament::test
