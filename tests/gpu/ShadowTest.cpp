// Cascaded shadow maps on the WARP device: a horizontal square hovering over flat ground, drawn
// into the cascades; at points of the ground the sun's visibility must be 0 where the ray to the
// sun meets the square and 1 where it does not (points within a few texels of the shadow's edge
// left out), for every combination of the cascades' options.
#include "gpu/KnownOccluder.h"
#include "gpu/WarpDevice.h"

#include "gpu/ConstantBuffer.h"
#include "shadows/CascadedShadowMaps.h"

#include <algorithm>
#include <cmath>
#include <cstdio>

namespace firmament::test {
namespace {

struct VisibilityQuery {
    glm::vec4 a, b;
};


class Shadows : public WarpDevice {
protected:
    // Renders the occluder into the cascades for `settings` and probes a grid of ground points.
    void check(ShadowSettings settings, const char* label) {
        Camera camera;
        camera.position = {10.0f, 150.0f, -100.0f};
        camera.yawDegrees = 5.0f;
        camera.pitchDegrees = -25.0f;
        Sun sun;
        sun.elevationDegrees = 35.0f;
        sun.azimuthDegrees = -30.0f;
        const glm::dvec3 toSun = glm::dvec3(sun.direction());

        CascadedShadowMaps shadows(device());
        shadows.update(context(), camera, 16.0 / 9.0, toSun, settings, 2000.0);
        drawKnownOccluder(device(), context(), *testShaderLibrary, shadows);

        std::vector<VisibilityQuery> queries;
        const glm::dvec3 forward = glm::dvec3(camera.forward());
        const glm::mat4 viewProjection = camera.projection(16.0f / 9.0f) * camera.view();
        for (double z = -20.0; z < 500.0; z += 3.7)
            for (double x = -200.0; x < 200.0; x += 4.3) {
                const glm::dvec3 p(x, 0.0, z);
                const glm::vec4 clip = viewProjection * glm::vec4(glm::vec3(p), 1.0f);  // points the camera sees
                if (clip.w <= 0.0f || std::abs(clip.x) > clip.w || std::abs(clip.y) > clip.w) continue;
                queries.push_back({glm::vec4(glm::vec3(p), static_cast<float>(glm::dot(p - glm::dvec3(camera.position), forward))),
                                   glm::vec4(0, 1, 0, 0)});
            }
        const auto results = runProbe({"shadows/shadow_probe.hlsl", "visibility", "cs_5_0", {}}, queries,
                                      {shadows.inputs().constants}, {shadows.inputs().map}, shadows.inputs().comparison);

        int shadowed = 0, lit = 0, skipped = 0;
        std::vector<int> perCascade(static_cast<size_t>(settings.cascades), 0);
        for (size_t i = 0; i < queries.size(); ++i) {
            const glm::dvec3 p(queries[i].a);
            const int cascade = static_cast<int>(results[i].y);
            ASSERT_GE(cascade, 0) << label << ": point " << p.x << ", " << p.z << " is in no cascade";
            ASSERT_LT(cascade, settings.cascades);
            ++perCascade[static_cast<size_t>(cascade)];
            if (settings.bestCascadeSearch) {  // no smaller cascade holds the point (with the filter's 2-texel margin)
                const double margin = 2.0 / shadowMapTexels(settings.resolution) + 1e-6;
                for (int smaller = 0; smaller < cascade; ++smaller) {
                    const glm::dvec4 uvz = shadows.cascades()[static_cast<size_t>(smaller)].worldToShadow * glm::dvec4(p, 1.0);
                    EXPECT_FALSE(uvz.x > margin && uvz.x < 1.0 - margin && uvz.y > margin && uvz.y < 1.0 - margin)
                        << label << ": point " << p.x << ", " << p.z << " is in cascade " << smaller << ", smaller than " << cascade;
                }
            } else {
                const auto& c = shadows.cascades()[static_cast<size_t>(cascade)];
                EXPECT_GE(queries[i].a.w, c.nearDepth - 1e-3) << label;
                EXPECT_LT(queries[i].a.w, c.farDepth + 1e-3) << label;
            }
            // Where the ray to the sun crosses the square's height, and how far inside it.
            const glm::dvec3 hit = p + toSun * (kSquareHeight / toSun.y);
            const double inside = std::min({hit.x - kSquare.x, double(kSquare.z) - hit.x, hit.z - kSquare.y, double(kSquare.w) - hit.z});
            const double texel = shadows.cascades()[static_cast<size_t>(cascade)].texelWorldSize;
            if (std::abs(inside) < 5.0 * texel / toSun.y) {
                ++skipped;
                continue;
            }
            if (inside > 0.0) {
                ++shadowed;
                EXPECT_LT(results[i].x, 0.01f) << label << ": point " << p.x << ", " << p.z << " (cascade " << cascade << ") should be in shadow";
            } else {
                ++lit;
                EXPECT_GT(results[i].x, 0.99f) << label << ": point " << p.x << ", " << p.z << " (cascade " << cascade << ") should be lit";
            }
        }
        std::printf("%s: %d shadowed, %d lit, %d near the edge; points per cascade:", label, shadowed, lit, skipped);
        for (int n : perCascade) std::printf(" %d", n);
        std::printf("\n");
        EXPECT_GT(shadowed, 100) << label;
        EXPECT_GT(lit, 500) << label;
        if (settings.cascades > 1) {
            EXPECT_GT(std::count_if(perCascade.begin(), perCascade.end(), [](int n) { return n > 0; }), 1)
                << label << ": more than one cascade serves the ground";
        }
    }
};

TEST_F(Shadows, KnownOccluderShadowsExactlyItsProjection) {
    for (const bool best : {true, false})
        for (const bool smooth : {true, false}) {
            ShadowSettings s;
            s.cascades = 4;
            s.bestCascadeSearch = best;
            s.smoothShadows = smooth;
            s.distanceKm = 1.0f;
            const std::string label = std::string("4 cascades, best search ") + (best ? "on" : "off") + ", smooth " + (smooth ? "on" : "off");
            check(s, label.c_str());
        }
}

TEST_F(Shadows, OneCascadeAndEightAtEveryResolution) {
    for (const int count : {1, 8})
        for (const ShadowMapResolution r : {ShadowMapResolution::R512, ShadowMapResolution::R4096}) {
            ShadowSettings s;
            s.cascades = count;
            s.resolution = r;
            s.distanceKm = 1.0f;
            const std::string label = std::to_string(count) + " cascade(s) of " + std::to_string(shadowMapTexels(r));
            check(s, label.c_str());
        }
}

}  // namespace
}  // namespace firmament::test
