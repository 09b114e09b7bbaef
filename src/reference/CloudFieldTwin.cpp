#include "reference/CloudFieldTwin.h"

#include "clouds/CloudGrid.h"
#include "core/IntegerHash.h"

#include <glm/common.hpp>
#include <glm/geometric.hpp>

#include <algorithm>
#include <cmath>

namespace firmament {

namespace {
float saturate(float x) { return std::clamp(x, 0.0f, 1.0f); }

// One tap of the density map at world (x, z): bilinear between the four texels around it,
// the map repeating every `1 / inversePeriod` metres, moved by the wind `offset`.
float densityTap(const std::vector<float>& map, int resolution, glm::vec2 xz, float inversePeriod, glm::vec2 offset) {
    const float res = static_cast<float>(resolution);
    const glm::vec2 c = (xz - offset) * inversePeriod * res - 0.5f;
    const glm::vec2 f(std::floor(c.x), std::floor(c.y));
    const glm::vec2 t = c - f;
    const std::uint32_t mask = static_cast<std::uint32_t>(resolution) - 1u;
    const int ix = static_cast<int>(f.x), iy = static_cast<int>(f.y);
    const std::uint32_t ax = static_cast<std::uint32_t>(ix) & mask, ay = static_cast<std::uint32_t>(iy) & mask;
    const std::uint32_t bx = static_cast<std::uint32_t>(ix + 1) & mask, by = static_cast<std::uint32_t>(iy + 1) & mask;
    auto at = [&](std::uint32_t x, std::uint32_t y) { return map[static_cast<size_t>(y) * resolution + x]; };
    return glm::mix(glm::mix(at(ax, ay), at(bx, ay), t.x), glm::mix(at(ax, by), at(bx, by), t.x), t.y);
}

// A point of the plane (x, z) lifted to `height` above the planet's surface, along the normal
// through it: the cloud layer follows the planet's curvature. The height y is written so that
// it does not cancel R against R in single precision.
glm::vec3 liftToLayer(glm::vec2 xz, float height, float radius) {
    const float d2 = xz.x * xz.x + xz.y * xz.y;
    const float length = std::sqrt(d2 + radius * radius);
    const float scale = (radius + height) / length;
    const float y = height * (radius / length) - radius * d2 / (length * (length + radius));
    return {xz.x * scale, y, xz.y * scale};
}
}  // namespace

CloudFieldModel modelCloudField(const gpu::CloudFieldConstants& c, const std::vector<std::uint32_t>& cells, const std::vector<float>& map,
                                glm::vec3 camera, float earthRadius) {
    CloudFieldModel model;
    const int resolution = static_cast<int>(c.coverage.w);
    const int rings = static_cast<int>(c.layout.x), dimension = static_cast<int>(c.layout.y), layers = static_cast<int>(c.layout.z);
    const float altitude = c.grid.y, thickness = c.grid.z, distance = c.grid.w;
    const int centreX = static_cast<int>(c.centre.x), centreZ = static_cast<int>(c.centre.y);
    model.coverage.resize(cells.size());
    model.reach.resize(cells.size());
    for (size_t index = 0; index < cells.size(); ++index) {
        const CloudCell cell = unpackCloudCell(cells[index]);
        const float size = std::ldexp(c.grid.x, cell.ring);
        const int kx = centreX * (1 << (rings - 1 - cell.ring)) + cell.i - dimension / 2;
        const int kz = centreZ * (1 << (rings - 1 - cell.ring)) + cell.j - dimension / 2;
        const glm::vec2 plane((static_cast<float>(kx) + 0.5f) * size, (static_cast<float>(kz) + 0.5f) * size);
        // Cloudiness: the geometric mean of the two taps, above the threshold it sets.
        const float n = std::sqrt(densityTap(map, resolution, plane, c.coverage.y, glm::vec2(c.wind.x, c.wind.y)) *
                                  densityTap(map, resolution, plane, c.coverage.z, glm::vec2(c.wind.z, c.wind.w)));
        const float unclamped = (n - (1.0f - c.coverage.x)) / std::max(c.coverage.x, 0.01f);
        const float coverage = saturate(unclamped);
        const float reach = glm::length(liftToLayer(plane, altitude, earthRadius) - camera) - (1.5f * size + 0.5f * thickness);
        model.coverage[index] = unclamped;
        model.reach[index] = reach;
        if (!(coverage > 0.0f) || reach > distance) continue;
        model.validCells.push_back(static_cast<unsigned>(index));
        for (int layer = 0; layer < layers; ++layer) {
            // The cell's coverage is the cloud's height: layers fill from the bottom up.
            const float layerDensity = saturate(coverage * static_cast<float>(layers) - static_cast<float>(layer));
            if (!(layerDensity > 0.0f)) continue;
            const std::uint32_t seed = hash32(static_cast<std::uint32_t>(kx) ^
                                              hash32(static_cast<std::uint32_t>(kz) ^ hash32(static_cast<std::uint32_t>(cell.ring * 32 + layer) + 0x9e3779b9u)));
            float r[7];
            for (int k = 0; k < 7; ++k) r[k] = unitFromHash(hash32(seed + static_cast<std::uint32_t>(k)));
            const glm::vec2 at = plane + glm::vec2(r[0] - 0.5f, r[1] - 0.5f) * (0.6f * size);
            const float height = altitude + ((static_cast<float>(layer) + 0.5f) / static_cast<float>(layers) - 0.5f) * thickness +
                                 (r[2] - 0.5f) * 0.5f * thickness / static_cast<float>(layers);
            ModelParticle p;
            p.centre = liftToLayer(at, height, earthRadius);
            const float pulse = 0.9f + 0.1f * std::sin(c.animation.x + 6.2831853f * r[4]);
            p.horizontalRadius = size * (0.7f + 0.4f * r[3]) * saturate(layerDensity * 3.0f) * pulse;
            p.verticalRadius = std::min(p.horizontalRadius, 0.75f * thickness / static_cast<float>(layers));
            p.density = layerDensity * (0.8f + 0.2f * std::sin(c.animation.y + 6.2831853f * r[5]));
            p.azimuth = 6.2831853f * r[6];
            p.ring = cell.ring;
            p.cell = static_cast<unsigned>(index);
            p.layer = layer;
            if (glm::length(p.centre - camera) - p.horizontalRadius > distance) continue;
            model.particles.push_back(p);
        }
    }
    return model;
}

}  // namespace firmament
