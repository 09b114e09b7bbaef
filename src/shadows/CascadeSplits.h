#pragma once
// Cascaded shadow maps' geometry on the CPU, in double precision (docs/shadows.md):
//  - the split distances, a blend of logarithmic and uniform partitions of the view depth
//    (Zhang et al. 2006, "parallel-split shadow maps"; Yusov 2013's "Partitioning factor");
//  - each cascade's orthographic light projection, stabilized (Valient 2008): a bounding sphere
//    of the frustum slice, whose radius depends only on the frustum's shape, so that the
//    projection's size never changes when the camera turns or moves, and a centre snapped to
//    whole texels in a light space that does not move with the camera, so that a world point
//    only ever moves by whole texels in the map.
#include <glm/glm.hpp>

#include <vector>

namespace firmament {

// Split i of `count` over [nearDepth, farDepth], i = 0..count (split 0 is nearDepth, split count farDepth):
//   z_i = lambda n (f / n)^(i / count) + (1 - lambda) (n + (f - n) i / count), n = nearDepth, f = farDepth.
std::vector<double> cascadeSplits(double nearDepth, double farDepth, int count, double lambda);

// The camera as the cascades see it.
struct CascadeCamera {
    glm::dvec3 position{};
    glm::dvec3 forward{0, 0, 1};
    double tanHalfFovY = 0.41421356;
    double aspectRatio = 16.0 / 9.0;
};

// Rotation from world to light space: x, y across the sun's rays, z along them (away from the
// sun). No translation: light space stays put when the camera moves.
glm::dmat4 lightViewMatrix(glm::dvec3 directionToSun);

struct Cascade {
    double nearDepth = 0, farDepth = 0;  // the view-depth range it covers
    glm::dvec3 centre{};                  // of its bounding sphere, world
    double radius = 0;                    // of its bounding sphere
    double texelWorldSize = 0;            // the map covers resolution texels of this size, a little more than 2 radius
    glm::dmat4 worldToClip{1.0};          // orthographic: x, y in [-1, 1], depth in [0, 1]
    glm::dmat4 worldToShadow{1.0};        // (u, v, depth): u, v in [0, 1], v down as textures are
};

// The cascade for view depths [nearDepth, farDepth]. casterReach: how far towards the sun
// beyond the sphere the depth range extends, so that distant mountains still cast shadows.
// aroundCamera: the sphere bounds the frustum from the camera's place (depth 0) to farDepth
// instead, as the light shafts' first marched cascade must, since their march starts at the
// camera (Yusov 2013; Intel's sample grows that cascade's box to hold the camera). The far
// corners set the sphere's size, so it grows little: its texels 1.4% for the default split 1 to 2.
Cascade fitCascade(const CascadeCamera& camera, double nearDepth, double farDepth, const glm::dmat4& lightView, int resolution,
                   double casterReach, bool aroundCamera = false);

}  // namespace firmament
