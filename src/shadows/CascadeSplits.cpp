#include "shadows/CascadeSplits.h"

#include <algorithm>
#include <cmath>

namespace firmament {

std::vector<double> cascadeSplits(double nearDepth, double farDepth, int count, double lambda) {
    std::vector<double> splits(static_cast<size_t>(count) + 1);
    for (int i = 0; i <= count; ++i) {
        const double t = static_cast<double>(i) / count;
        const double logarithmic = nearDepth * std::pow(farDepth / nearDepth, t);
        const double uniform = nearDepth + (farDepth - nearDepth) * t;
        splits[static_cast<size_t>(i)] = lambda * logarithmic + (1.0 - lambda) * uniform;
    }
    splits.front() = nearDepth;  // exact ends, whatever pow rounds to
    splits.back() = farDepth;
    return splits;
}

glm::dmat4 lightViewMatrix(glm::dvec3 directionToSun) {
    const glm::dvec3 forward = -glm::normalize(directionToSun);  // the light's rays
    const glm::dvec3 helper = std::abs(forward.y) < 0.99 ? glm::dvec3(0, 1, 0) : glm::dvec3(0, 0, 1);
    const glm::dvec3 right = glm::normalize(glm::cross(helper, forward));  // left-handed: x = up x z
    const glm::dvec3 up = glm::cross(forward, right);
    glm::dmat4 view(1.0);
    for (int c = 0; c < 3; ++c) {  // rows right, up, forward (GLM is column-major: view[column][row])
        view[c][0] = right[c];
        view[c][1] = up[c];
        view[c][2] = forward[c];
    }
    return view;
}

Cascade fitCascade(const CascadeCamera& camera, double nearDepth, double farDepth, const glm::dmat4& lightView, int resolution,
                   double casterReach, bool aroundCamera) {
    Cascade c;
    c.nearDepth = nearDepth;
    c.farDepth = farDepth;
    const double fitNear = aroundCamera ? 0.0 : nearDepth;  // the camera is the apex: the slice [0, far] is the whole pyramid
    // The smallest sphere about the view axis through the slice's corners: the corners at depth
    // z lie k z off the axis, k the tangent of the half diagonal. Equal distance to the near and
    // far corners puts the centre at (near + far)(1 + k^2) / 2, no farther than the far plane.
    const double tanHalfFovX = camera.tanHalfFovY * camera.aspectRatio;
    const double k2 = camera.tanHalfFovY * camera.tanHalfFovY + tanHalfFovX * tanHalfFovX;
    const double centreDepth = std::min((fitNear + farDepth) * (1.0 + k2) * 0.5, farDepth);
    const double farOffAxis2 = k2 * farDepth * farDepth;
    c.radius = std::sqrt(farOffAxis2 + (farDepth - centreDepth) * (farDepth - centreDepth));
    c.centre = camera.position + glm::normalize(camera.forward) * centreDepth;
    // Snapping moves the square by up to a texel: its half-width is the radius and one texel more,
    // halfWidth = radius * resolution / (resolution - 2), a whole number (resolution / 2) of texels.
    const double halfWidth = c.radius * resolution / (resolution - 2.0);
    c.texelWorldSize = 2.0 * halfWidth / resolution;

    // Snap the centre to whole texels in light space.
    glm::dvec3 centre = glm::dvec3(lightView * glm::dvec4(c.centre, 1.0));
    centre.x = std::floor(centre.x / c.texelWorldSize) * c.texelWorldSize;
    centre.y = std::floor(centre.y / c.texelWorldSize) * c.texelWorldSize;
    const double zNear = centre.z - c.radius - casterReach, zFar = centre.z + c.radius;

    glm::dmat4 projection(0.0);  // light space to clip: x, y to [-1, 1], z to [0, 1]
    projection[0][0] = 1.0 / halfWidth;
    projection[1][1] = 1.0 / halfWidth;
    projection[2][2] = 1.0 / (zFar - zNear);
    projection[3][0] = -centre.x / halfWidth;
    projection[3][1] = -centre.y / halfWidth;
    projection[3][2] = -zNear / (zFar - zNear);
    projection[3][3] = 1.0;
    c.worldToClip = projection * lightView;
    glm::dmat4 clipToTexture(1.0);  // u = x / 2 + 1/2, v = -y / 2 + 1/2
    clipToTexture[0][0] = 0.5;
    clipToTexture[1][1] = -0.5;
    clipToTexture[3][0] = 0.5;
    clipToTexture[3][1] = 0.5;
    c.worldToShadow = clipToTexture * c.worldToClip;
    return c;
}

}  // namespace firmament
