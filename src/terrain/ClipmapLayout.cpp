#include "terrain/ClipmapLayout.h"

#include <glm/common.hpp>

#include <cmath>

namespace firmament {

int holeFirstCell(int offset) { return kClipmapCells / 4 + offset; }

ClipmapExtent clipmapExtent(glm::dvec2 camera) {
    const ClipmapLevel coarsest = clipmapLevels(camera, 0.0).back();
    const double halfWidth = (kClipmapCells / 2) * coarsest.spacing;
    return {coarsest.origin + halfWidth, halfWidth};
}

std::vector<ClipmapLevel> clipmapLevels(glm::dvec2 camera, double heightAboveGround) {
    constexpr int half = kClipmapCells / 2;
    int finest = 0;
    while (finest + 1 < kClipmapLevels && half * kFinestSpacing * std::ldexp(1.0, finest) < kLevelReachOverHeight * heightAboveGround) ++finest;
    std::vector<ClipmapLevel> levels;
    glm::dvec2 finerCentre{};
    for (int L = finest; L < kClipmapLevels; ++L) {
        ClipmapLevel level;
        level.index = L;
        level.spacing = kFinestSpacing * std::ldexp(1.0, L);
        const double snap = 2.0 * level.spacing;
        const glm::dvec2 centre = glm::floor(camera / snap + 0.5) * snap;
        level.origin = centre - static_cast<double>(half) * level.spacing;
        if (L > finest) {
            level.hasHole = true;
            const glm::dvec2 offset = (finerCentre - centre) / level.spacing;  // whole cells, within [-1, 1]
            level.holeOffset = glm::ivec2(static_cast<int>(std::lround(offset.x)), static_cast<int>(std::lround(offset.y)));
        }
        finerCentre = centre;
        levels.push_back(level);
    }
    return levels;
}

}  // namespace firmament
