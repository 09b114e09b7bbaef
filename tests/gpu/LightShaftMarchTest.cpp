// The light shafts' ray march (shaders/lightshafts/ray_march.hlsli) on the WARP device, against
// a CPU computation with a known occluder: the shadow test's horizontal square hovering 45 m
// over flat ground, drawn into the cascades. Along rays from a camera above it and from one in
// its shadow, the lit length D_lit and the distance to the first lit point D_start must equal
// the geometry's (the ray's part under the square whose way to the sun meets the square), and
// the in-scattering integrated over the lit steps must equal the reference atmosphere's
// integral over the lit parts of the ray. Two set-ups: four cascades reaching 1 km marched from
// cascade 0, and the defaults (four cascades reaching 100 km, marched from cascade 1, whose split
// lies 1.3 km away: the square and every ray lie nearer than it). The table modes (LUT, occluded
// and unoccluded higher orders) are held to the geometry's lit section, and to the CPU within the
// table's own error: LUT to single scattering's integral, the higher orders to Monte Carlo
// (checkTableModes, checkHighOrders).
#include "FrameTest.h"
#include "KnownOccluder.h"
#include "atmosphere/Atmosphere.h"
#include "atmosphere/AtmosphereParameters.h"
#include "core/Camera.h"
#include "gpu/CommonStates.h"
#include "lightshafts/LightShafts.h"
#include "reference/ReferenceAtmosphere.h"
#include "shadows/CascadedShadowMaps.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdio>
#include <map>
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
// view_ray.hlsli's kSingleTable and kHighOrderTable: which table march_probe.hlsl's section and
// lookUp entries read.
constexpr int kSingleTableId = 1, kHighOrderTableId = 2;


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

// The section eq. 8 takes along the ray, from the geometry: from the first lit point, the lit
// length (Yusov 2013's approximation: the lit parts taken as one section).
glm::dvec2 litSection(glm::dvec3 c, glm::dvec3 v, double length, glm::dvec3 toSun) {
    const glm::dvec2 shadow = shadowInterval(c, v, length, toSun);
    const double shadowed = shadow.y - shadow.x;
    const double firstLit = shadowed > 0.0 && shadow.x <= 0.0 ? shadow.y : 0.0;
    return {firstLit, std::min(firstLit + (length - shadowed), length)};
}

// Single scattering's integrand along the ray start + s v (start from the Earth's centre), per
// unit irradiance: scattering towards the camera times the transmittances to the camera and to
// the sun (Yusov 2013, eq. 1 without the integral).
glm::dvec3 singleScatteringIntegrand(const atmosphere::ReferenceAtmosphere& reference, const AtmosphereParameters& p, glm::dvec3 start,
                                     glm::dvec3 v, glm::dvec3 toSun, double s) {
    const double cosTheta = glm::dot(v, toSun);
    const glm::dvec3 point = start + v * s;
    const glm::dvec3 rho = reference.density(glm::length(point) - p.earthRadius);
    const glm::dvec3 toCamera = glm::exp(-reference.opticalDepth(reference.netDensity(start, point)));
    const glm::dvec3 beta = p.rayleighScattering * rho.x * atmosphere::rayleighPhase(cosTheta) +
                            p.mieScattering * rho.y * atmosphere::miePhase(cosTheta, p.mieAsymmetry);
    return beta * toCamera * reference.sunTransmittance(point, toSun);
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

    // What the march found along a grid of the camera's rays (to the ground or kMaxRayLength)
    // through cascades holding the square, in the render modes of `settings`: per ray the march
    // (D_lit, D_start, begin, end), the shadowed in-scattering and the unshadowed one (the whole
    // ray, as the atmosphere's passes draw it), per unit irradiance.
    // With `table` (view_ray.hlsli's kSingleTable, kHighOrderTable), also eq. 8 from that table
    // over each ray's lit section as the geometry has it (litSection), and the table's look-ups
    // at the section's ends.
    struct Probed {
        std::vector<RayQuery> queries;
        std::vector<glm::vec4> marched, scattered, unshadowed;
        std::vector<glm::vec4> section, sectionStart, sectionEnd;  // with a table
        std::vector<glm::vec4> rayStart, rayEnd;  // with a table: its look-ups at the camera and at the ray's end
        std::vector<glm::vec4> nearStart, nearEnd;  // eq. 8 within the lit length's tolerance of the section's ends
        std::vector<Cascade> cascades;
    };

    Probed probe(const Case& c, Atmosphere& atmosphere, const AtmosphereSettings& atmosphereSettings, int table = 0) {
        const Sun sun = testSun();
        const glm::dvec3 toSun = glm::dvec3(sun.direction());
        CascadedShadowMaps shadows(device());
        shadows.update(context(), c.camera, 16.0 / 9.0, toSun, c.shadows, 2000.0, c.firstCascade);
        drawKnownOccluder(device(), context(), *testShaderLibrary, shadows);

        gpu::FrameConstants constants{};
        FrameContext frame{device(), context(), *productShaderLibrary, *profiler, targets, frameConstants->get(), constants, c.camera, sun,
                           0.0, 1.0 / 60.0, true};
        atmosphere.update(frame, atmosphereSettings);
        const ScatteringLookup lookup = atmosphere.scatteringLookup(frame, atmosphereSettings);
        EXPECT_TRUE(lookup.ready);
        LightShaftSettings shaftSettings;
        shaftSettings.firstCascade = c.firstCascade;
        ConstantBuffer<gpu::LightShaftConstants> shaftConstants(device());
        shaftConstants.update(context(), LightShafts::constants(shaftSettings, lookup, shadows.inputs().resolution));
        ConstantBuffer<ProbeConstants> probeConstants(device());
        probeConstants.update(context(), ProbeConstants{glm::vec4(c.camera.position, 1.0f), glm::vec4(glm::vec3(toSun), 0.0f)});

        Probed r;
        const glm::mat4 toWorld = glm::inverse(c.camera.projection(16.0f / 9.0f) * c.camera.view());
        const glm::dvec3 camera(c.camera.position);
        for (int y = 0; y < 18; ++y)
            for (int x = 0; x < 32; ++x) {
                const glm::vec4 farPoint = toWorld * glm::vec4((x + 0.5f) / 32.0f * 2.0f - 1.0f, 1.0f - (y + 0.5f) / 18.0f * 2.0f, 0.5f, 1.0f);
                const glm::dvec3 v = glm::normalize(glm::dvec3(farPoint) / static_cast<double>(farPoint.w) - camera);
                const double length = v.y < 0.0 ? std::min(-camera.y / v.y, kMaxRayLength) : kMaxRayLength;
                r.queries.push_back({glm::vec4(glm::vec3(v), static_cast<float>(length)), glm::vec4(0.0f)});
            }
        const ShadowInputs inputs = shadows.inputs();
        context()->CSSetSamplers(1, 1, &inputs.comparison);
        const std::initializer_list<ID3D11ShaderResourceView*> tables{lookup.netDensity, lookup.singleScattering, lookup.highOrderScattering,
                                                                       lookup.multipleScattering, inputs.map};
        const std::initializer_list<ID3D11Buffer*> buffers{lookup.atmosphere, shaftConstants.get(), inputs.constants, probeConstants.get()};
        r.marched = runProbe({"lightshafts/march_probe.hlsl", "march", "cs_5_0", {}}, r.queries, buffers, tables, lookup.linearClamp);
        r.scattered = runProbe({"lightshafts/march_probe.hlsl", "inscattering", "cs_5_0", {}}, r.queries, buffers, tables, lookup.linearClamp);
        r.unshadowed = runProbe({"lightshafts/march_probe.hlsl", "unshadowed", "cs_5_0", {}}, r.queries, buffers, tables, lookup.linearClamp);
        if (table != 0) {
            std::vector<RayQuery> sections = r.queries, starts = r.queries, ends = r.queries, nearStarts = r.queries, nearEnds = r.queries;
            std::vector<RayQuery> rayStarts = r.queries, rayEnds = r.queries;
            for (size_t i = 0; i < r.queries.size(); ++i) {
                const glm::dvec3 v(r.queries[i].a);
                const double length = r.queries[i].a.w;
                const glm::dvec2 lit = litSection(camera, v, length, glm::dvec3(toSun));
                const double tolerance = litLengthTolerance(c, shadows.cascades(), v, length);
                const auto query = [&](double s0, double s1) {
                    return glm::vec4(static_cast<float>(std::max(s0, 0.0)), static_cast<float>(std::min(s1, length)), static_cast<float>(table), 0.0f);
                };
                sections[i].b = query(lit.x, lit.y);
                starts[i].b = query(lit.x, 0.0);
                ends[i].b = query(lit.y, 0.0);
                nearStarts[i].b = query(lit.x - tolerance, lit.x + tolerance);
                nearEnds[i].b = query(lit.y - tolerance, lit.y + tolerance);
                rayStarts[i].b = query(0.0, 0.0);
                rayEnds[i].b = query(length, 0.0);
            }
            const auto run = [&](const char* entry, const std::vector<RayQuery>& q) {
                return runProbe({"lightshafts/march_probe.hlsl", entry, "cs_5_0", {}}, q, buffers, tables, lookup.linearClamp);
            };
            r.section = run("section", sections);
            r.sectionStart = run("lookUp", starts);
            r.sectionEnd = run("lookUp", ends);
            r.nearStart = run("section", nearStarts);
            r.nearEnd = run("section", nearEnds);
            r.rayStart = run("lookUp", rayStarts);
            r.rayEnd = run("lookUp", rayEnds);
        }
        r.cascades = shadows.cascades();
        return r;
    }

    // The tolerance of a ray's lit length: one march step is a texel of the coarsest cascade
    // crossed at most, along the ray: its length across the sun's direction. Two edges, each off
    // by a step and the filter's half texel. Where the ray enters the shadow under the square,
    // the casters' slope-scaled bias (2 texels of the square's depth slope, cot(elevation) per
    // texel) lets it stay lit while its depth below the square grows, at |v.y| / sin(elevation)
    // per metre.
    static double litLengthTolerance(const Case& c, const std::vector<Cascade>& cascades, glm::dvec3 v, double length) {
        const glm::dvec3 toSun = glm::dvec3(testSun().direction());
        const glm::dvec3 forward = glm::normalize(glm::dvec3(c.camera.forward()));
        // The coarsest cascade the march crosses: the one holding the ray's end, or the first marched.
        size_t coarsest = static_cast<size_t>(c.firstCascade);
        while (coarsest + 1 < cascades.size() && length * glm::dot(v, forward) > cascades[coarsest].farDepth) ++coarsest;
        const double texel = cascades[coarsest].texelWorldSize;
        const double across = std::max(glm::length(v - toSun * glm::dot(v, toSun)), 0.05);
        const double cosElevation = std::sqrt(1.0 - toSun.y * toSun.y);
        return texel * (3.0 / across + 2.5 * cosElevation / std::max(std::abs(v.y), 0.05)) + 0.05;
    }

    void check(const Case& c) {
        const glm::dvec3 toSun = glm::dvec3(testSun().direction());
        // Small tables: the march, not the tables, is under test; single scattering integrated.
        AtmosphereSettings atmosphereSettings;
        atmosphereSettings.resolution = LutResolution::Small;
        atmosphereSettings.scatteringOrders = 1;
        atmosphereSettings.singleScattering = SingleScatteringMode::Integration;
        atmosphereSettings.multipleScattering = MultipleScatteringMode::None;
        Atmosphere atmosphere(device(), TableStorage{});
        const Probed probed = probe(c, atmosphere, atmosphereSettings);
        const std::vector<RayQuery>& queries = probed.queries;
        const auto& marched = probed.marched;
        const auto& scattered = probed.scattered;
        const glm::dvec3 camera(c.camera.position);

        const AtmosphereParameters p = AtmosphereParameters::from(atmosphereSettings);
        const atmosphere::ReferenceAtmosphere reference(p);
        const glm::dvec3 earthCentre(0.0, -p.earthRadius, 0.0);
        int crossing = 0, worstRay = -1;
        double worstLit = 0.0, worstScattering = 0.0;
        for (size_t i = 0; i < queries.size(); ++i) {
            const glm::dvec3 v(queries[i].a);
            const double length = queries[i].a.w;
            const glm::dvec2 shadow = shadowInterval(camera, v, length, toSun);
            const double shadowed = shadow.y - shadow.x;
            crossing += shadowed > 1.0;
            const double tolerance = litLengthTolerance(c, probed.cascades, v, length);
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
            const auto integrand = [&](double s) { return singleScatteringIntegrand(reference, p, start, v, toSun, s); };
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


    // The table modes (Yusov 2013, eq. 8 over the lit section [D_start, D_start + D_lit]), Medium
    // tables with four orders, on the rays that end at the ground. Two things are held apart:
    //  - the march and eq. 8's assembly: the light in each mode (LUT; Occluded higher orders)
    //    equals eq. 8 from the same table over the lit section as the geometry has it
    //    (litSection), within the table's light over the lit length's tolerance at each end of
    //    the section (and 10^-4 of the ray's light for float sums);
    //  - LUT against the CPU integral of single scattering over the lit parts. Allowed: eq. 8's
    //    approximation (the lit parts taken as one section from the first lit point: exact for a
    //    ray that leaves the shadow and stays lit, computed here from the geometry), the table's
    //    own error at the section's two ends (its look-ups against the CPU's integral from there
    //    to the ground, times the transmittance), the assembly's allowance (the lit length's
    //    tolerance), and 2% of the light (the look-ups' transmittances from the net density table).
    //  - Unoccluded higher orders: the whole-ray light whatever the shadow.
    // The higher orders have no CPU integral along a ray (their tables are held to Monte Carlo at
    // random points: AtmosphereTables.HighOrderScatteringMatchesMonteCarlo). On a ray that ends in
    // mid-air (these end at 800 m) both of eq. 8's look-ups hold the whole sky beyond, and their
    // difference carries the table's error of that, which is no fault of the march.
    void checkTableModes(const Case& c) {
        const glm::dvec3 toSun = glm::dvec3(testSun().direction());
        AtmosphereSettings settings;
        settings.resolution = LutResolution::Medium;
        settings.scatteringOrders = 4;
        // The same tables for every case (Medium, 4 orders): computed at the first.
        if (!atmosphere_) atmosphere_ = std::make_unique<Atmosphere>(device(), TableStorage{});
        Atmosphere& atmosphere = *atmosphere_;
        settings.singleScattering = SingleScatteringMode::Table;
        settings.multipleScattering = MultipleScatteringMode::None;
        const Probed lut = probe(c, atmosphere, settings, kSingleTableId);
        settings.singleScattering = SingleScatteringMode::None;
        settings.multipleScattering = MultipleScatteringMode::Occluded;
        const Probed occluded = probe(c, atmosphere, settings, kHighOrderTableId);
        settings.multipleScattering = MultipleScatteringMode::Unoccluded;
        const Probed unoccluded = probe(c, atmosphere, settings);

        const AtmosphereParameters p = AtmosphereParameters::from(settings);
        const atmosphere::ReferenceAtmosphere reference(p);
        const glm::dvec3 camera(c.camera.position);
        const glm::dvec3 start = camera - glm::dvec3(0.0, -p.earthRadius, 0.0);
        const auto over = [](const auto& f, double a, double b) { return b > a ? atmosphere::gaussLegendre3(f, a, b, 4) : glm::dvec3(0.0); };
        double worstLutAssembly = 0.0, worstOccludedAssembly = 0.0, worstLut = 0.0, worstUnoccluded = 0.0;
        double largestApproximation = 0.0, largestTableError = 0.0;
        int toTheGround = 0, crossing = 0;
        std::vector<size_t> crossingRays;
        for (size_t i = 0; i < lut.queries.size(); ++i) {
            const glm::dvec3 v(lut.queries[i].a);
            const double length = lut.queries[i].a.w;
            const double unoccludedError = std::abs(unoccluded.scattered[i].b - unoccluded.unshadowed[i].b) / unoccluded.unshadowed[i].b;
            EXPECT_LT(unoccludedError, 1e-5) << c.label << ", Unoccluded, ray " << i << ": " << unoccluded.scattered[i].b << " with the shadow, "
                                             << unoccluded.unshadowed[i].b << " without";
            worstUnoccluded = std::max(worstUnoccluded, unoccludedError);
            if (!(v.y < 0.0 && -camera.y / v.y <= kMaxRayLength)) continue;  // ends in mid-air
            ++toTheGround;
            const glm::dvec2 shadow = shadowInterval(camera, v, length, toSun);
            const double shadowed = shadow.y - shadow.x;
            crossing += shadowed > 1.0;
            if (shadowed > 1.0) crossingRays.push_back(i);
            const glm::dvec2 section = litSection(camera, v, length, toSun);
            const auto integrand = [&](double s) { return singleScatteringIntegrand(reference, p, start, v, toSun, s); };

            // The assembly: a lit length off by the tolerance moves a section's end by as much, and
            // eq. 8 by at most the table's light within the tolerance of each end (eq. 8 from the
            // same table over those stretches), plus 10^-4 of the ray's light for float sums.
            const auto assemblyAllowance = [&](const Probed& probed) {
                return probed.nearStart[i].b + probed.nearEnd[i].b + 1e-4 * probed.unshadowed[i].b;
            };
            const double lutAllowance = assemblyAllowance(lut);
            const double occludedAllowance = assemblyAllowance(occluded);
            const double lutAssembly = std::abs(lut.scattered[i].b - lut.section[i].b);
            EXPECT_LT(lutAssembly, lutAllowance) << c.label << ", LUT, ray " << i << ": " << lut.scattered[i].b
                                                           << ", eq. 8 over the geometry's section " << lut.section[i].b;
            worstLutAssembly = std::max(worstLutAssembly, lutAssembly / lutAllowance);
            const double occludedAssembly = std::abs(occluded.scattered[i].b - occluded.section[i].b);
            EXPECT_LT(occludedAssembly, occludedAllowance) << c.label << ", Occluded, ray " << i << ": " << occluded.scattered[i].b
                                                                     << ", eq. 8 over the geometry's section " << occluded.section[i].b;
            worstOccludedAssembly = std::max(worstOccludedAssembly, occludedAssembly / occludedAllowance);

            // LUT against the CPU integral over the lit parts.
            const glm::dvec3 whole = over(integrand, 0.0, length);
            const glm::dvec3 lit = shadowed > 0.0 ? over(integrand, 0.0, shadow.x) + over(integrand, shadow.y, length) : whole;
            const double approximation = std::abs(over(integrand, section.x, section.y).b - lit.b);
            largestApproximation = std::max(largestApproximation, approximation / whole.b);
            // The table's error at a point s of the ray: its look-up against the CPU's integral from
            // there to the ground, times the transmittance from the camera.
            const auto tableError = [&](double s, const glm::vec4& looked) {
                const glm::dvec3 from = start + v * s;
                const glm::dvec3 rest = over([&](double t) { return singleScatteringIntegrand(reference, p, from, v, toSun, t); }, 0.0, length - s);
                return looked.w * std::abs(looked.b - rest.b);
            };
            const double table = tableError(section.x, lut.sectionStart[i]) + tableError(section.y, lut.sectionEnd[i]);
            largestTableError = std::max(largestTableError, table / whole.b);
            const double lutAllowed = approximation + table + lutAllowance + 0.02 * lut.scattered[i].b;
            const double lutError = std::abs(lut.scattered[i].b - lit.b);
            EXPECT_LT(lutError, lutAllowed) << c.label << ", LUT, ray " << i << ": " << lut.scattered[i].b << ", expected " << lit.b
                                            << " (approximation " << approximation << ", table " << table << ")";
            worstLut = std::max(worstLut, lutError / lutAllowed);
        }
        if (highOrders_) checkHighOrders(c, occluded, unoccluded, reference, crossingRays);
        std::printf("%s: %d rays to the ground, %d through the shadow. Largest error of its allowance: assembly LUT %.2f, Occluded %.2f; "
                    "LUT against the CPU %.2f (eq. 8's approximation up to %.3f of the whole ray, the table's error at the ends up to "
                    "%.3f); Unoccluded against the unshadowed ray (%zu rays) %.1e\n",
                    c.label, toTheGround, crossing, worstLutAssembly, worstOccludedAssembly, worstLut, largestApproximation, largestTableError,
                    lut.queries.size(), worstUnoccluded);
        EXPECT_GT(crossing, 60) << c.label << ": too few rays to the ground cross the shadow to test it";
    }

    // The higher orders (orders 2 to 4) against Monte Carlo, on kHighOrderRays of the rays to the
    // ground that cross the shadow. M(s), the light of the higher orders from the point s of the
    // ray to the ground (ReferenceAtmosphere::highOrderScattering, the ground black as in the
    // tables), gives the light over a part [a, b] as T(0, a) M(a) - T(0, b) M(b).
    //  - Occluded (the higher orders taken as shadowed with the sun's light, as the mode defines
    //    them) against the CPU's light over the lit parts. Allowed, as for LUT: eq. 8's
    //    approximation, the table's error at the section's ends (its look-ups against M there),
    //    the assembly's allowance and 2%, plus 4 standard errors of the estimates (each estimate
    //    enters the error and its allowance at most twice).
    //  - Unoccluded against the CPU's light over the whole ray, M(0). The mode marches nothing:
    //    it is eq. 8 over the whole ray, so what it can get wrong is which table it reads and how
    //    it takes the ends. Allowed: the table's error at the camera (its look-up against M(0)),
    //    its light at the ray's end (where M is zero), 2% and 4 standard errors. On these short
    //    rays near the ground the Medium table itself is several times off (docs/atmosphere.md,
    //    "Short rays to the ground"); AtmosphereTables holds it to Monte Carlo where it is not.
    // The rays chosen have a lit part: rays wholly in shadow down to the ground carry no light in
    // the Occluded mode, and would test nothing.
    // The reference's Monte Carlo estimate of orders 2 to 4 from `point` along v, 4000 paths,
    // kept: the two set-ups of cascades send the same rays.
    atmosphere::ReferenceAtmosphere::Estimate highOrders(const atmosphere::ReferenceAtmosphere& reference, glm::dvec3 point, glm::dvec3 v,
                                                         glm::dvec3 toSun, unsigned seed) {
        const std::array<double, 6> key{point.x, point.y, point.z, v.x, v.y, v.z};
        const auto known = highOrderEstimates_.find(key);
        if (known != highOrderEstimates_.end()) return known->second;
        return highOrderEstimates_[key] = reference.highOrderScattering(point, v, toSun, 4, 4000, seed);
    }
    std::map<std::array<double, 6>, atmosphere::ReferenceAtmosphere::Estimate> highOrderEstimates_;
    bool highOrders_ = false;  // checkTableModes also holds the higher orders to Monte Carlo (about 40 s)
    std::unique_ptr<Atmosphere> atmosphere_;  // checkTableModes' tables, shared by its cases
    void checkTableModesAtTheNearCascades();
    void checkTableModesAtBothSetUps();

    void checkHighOrders(const Case& c, const Probed& occluded, const Probed& unoccluded, const atmosphere::ReferenceAtmosphere& reference,
                         const std::vector<size_t>& crossingRays) {
        constexpr size_t kHighOrderRays = 6;
        const AtmosphereParameters& p = reference.parameters();
        const glm::dvec3 toSun = glm::dvec3(testSun().direction());
        const glm::dvec3 camera(c.camera.position);
        std::vector<size_t> partlyLit;
        for (const size_t i : crossingRays) {
            const double length = occluded.queries[i].a.w;
            const glm::dvec2 shadow = shadowInterval(camera, glm::dvec3(occluded.queries[i].a), length, toSun);
            if (shadow.x > 1.0 || shadow.y < length - 1.0) partlyLit.push_back(i);
        }
        ASSERT_GE(partlyLit.size(), kHighOrderRays) << c.label << ": too few rays through the shadow have a lit part";
        const glm::dvec3 start = camera - glm::dvec3(0.0, -p.earthRadius, 0.0);
        double worstOccluded = 0.0, worstUnoccluded = 0.0, worstUnoccludedAllowance = 0.0, largestTableError = 0.0;
        for (size_t k = 0; k < kHighOrderRays; ++k) {
            const size_t i = partlyLit[k * partlyLit.size() / kHighOrderRays];
            const glm::dvec3 v(occluded.queries[i].a);
            const double length = occluded.queries[i].a.w;
            const glm::dvec2 shadow = shadowInterval(camera, v, length, toSun);
            const glm::dvec2 section = litSection(camera, v, length, toSun);
            // T(0, s), blue.
            const auto transmittance = [&](double s) {
                return std::exp(-reference.opticalDepth(reference.netDensity(start, start + v * std::min(s, length))).b);
            };
            // T(0, s) M(s) and its standard error, blue; M is zero at the ground.
            struct Weighted { double light, error; };
            unsigned seed = 7000u + static_cast<unsigned>(i) * 8u;
            const auto weighted = [&](double s) -> Weighted {
                if (s >= length - 1e-3) return {0.0, 0.0};
                const double t = transmittance(s);
                const auto e = highOrders(reference, start + v * s, v, toSun, seed++);
                return {t * e.mean.b, t * e.standardError.b};
            };
            const Weighted atCamera = weighted(0.0), shadowStart = shadow.x <= 0.0 ? atCamera : weighted(shadow.x), shadowEnd = weighted(shadow.y);
            const Weighted sectionStart = section.x == 0.0 ? atCamera : section.x == shadow.y ? shadowEnd : weighted(section.x);
            const Weighted sectionEnd = section.y >= length - 1e-3 ? Weighted{0.0, 0.0} : weighted(section.y);
            const double lit = atCamera.light - shadowStart.light + shadowEnd.light;
            const double sectionLight = sectionStart.light - sectionEnd.light;
            const double approximation = std::abs(sectionLight - lit);
            const auto lookedError = [&](const glm::vec4& looked, const Weighted& m, double s) { return std::abs(transmittance(s) * looked.b - m.light); };
            const double table = lookedError(occluded.sectionStart[i], sectionStart, section.x) + lookedError(occluded.sectionEnd[i], sectionEnd, section.y);
            largestTableError = std::max(largestTableError, table / atCamera.light);
            const double noise = 4.0 * 2.0 * std::sqrt(atCamera.error * atCamera.error + shadowStart.error * shadowStart.error +
                                                       shadowEnd.error * shadowEnd.error + sectionStart.error * sectionStart.error +
                                                       sectionEnd.error * sectionEnd.error);
            const double assembly = occluded.nearStart[i].b + occluded.nearEnd[i].b + 1e-4 * occluded.unshadowed[i].b;
            const double allowed = approximation + table + assembly + 0.02 * occluded.scattered[i].b + noise;
            const double error = std::abs(occluded.scattered[i].b - lit);
            EXPECT_LT(error, allowed) << c.label << ", Occluded, ray " << i << ": " << occluded.scattered[i].b << ", Monte Carlo " << lit
                                      << " (approximation " << approximation << ", table " << table << ", noise " << noise << ")";
            worstOccluded = std::max(worstOccluded, error / allowed);

            const double atTheCamera = std::abs(occluded.rayStart[i].b - atCamera.light);
            const double atTheEnd = occluded.rayEnd[i].w * occluded.rayEnd[i].b;
            const double unoccludedAllowed = atTheCamera + atTheEnd + 0.02 * unoccluded.scattered[i].b + 4.0 * atCamera.error;
            const double unoccludedError = std::abs(unoccluded.scattered[i].b - atCamera.light);
            EXPECT_LT(unoccludedError, unoccludedAllowed) << c.label << ", Unoccluded, ray " << i << ": " << unoccluded.scattered[i].b
                                                          << ", Monte Carlo " << atCamera.light << " +- " << atCamera.error;
            worstUnoccludedAllowance = std::max(worstUnoccludedAllowance, unoccludedError / unoccludedAllowed);
            worstUnoccluded = std::max(worstUnoccluded, unoccludedError / atCamera.light);
            std::printf("  ray %zu: Occluded %.3e, Monte Carlo %.3e (approximation %.1e, table %.1e, noise %.1e); Unoccluded %.3e, Monte Carlo %.3e +- %.1e\n",
                        i, occluded.scattered[i].b, lit, approximation, table, noise, unoccluded.scattered[i].b, atCamera.light, atCamera.error);
        }
        std::printf("%s: higher orders against Monte Carlo on %zu rays: Occluded's largest error %.2f of its allowance (the table's error at "
                    "the ends up to %.3f of the whole ray); Unoccluded's %.2f of its allowance (relative error %.3f, the table's)\n",
                    c.label, kHighOrderRays, worstOccluded, largestTableError, worstUnoccludedAllowance, worstUnoccluded);
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

// The table modes against the CPU at both set-ups: the near cascades marched from 0, and the
// defaults, where the square and the rays lie nearer than split 1. The quick tier holds LUT and the
// lit section at the near cascades (ACasterNearerThanTheFirstMarchedSplitShadowsTheHazeAtTheDefaults
// holds the defaults' geometry); the full tier both set-ups, with the higher orders against Monte
// Carlo (4000 paths a point).
void LightShaftMarch::checkTableModesAtTheNearCascades() {
    checkTableModes({"camera above the square", cameraAboveTheSquare(), false, nearCascades(), 0});
    checkTableModes({"camera in the shadow", cameraInTheShadow(), true, nearCascades(), 0});
}

void LightShaftMarch::checkTableModesAtBothSetUps() {
    checkTableModesAtTheNearCascades();
    const LightShaftSettings defaults;
    checkTableModes({"defaults, camera above the square", cameraAboveTheSquare(), false, ShadowSettings{}, defaults.firstCascade});
    checkTableModes({"defaults, camera in the shadow", cameraInTheShadow(), true, ShadowSettings{}, defaults.firstCascade});
}

TEST_F(LightShaftMarch, TheTableModesMatchTheCpuOverTheLitSection) { checkTableModesAtTheNearCascades(); }

TEST_F(LightShaftMarch, TheHigherOrdersMatchMonteCarloOverTheLitSection) {
    highOrders_ = true;
    checkTableModesAtBothSetUps();
}

}  // namespace
}  // namespace firmament::test
