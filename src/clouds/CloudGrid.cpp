#include "clouds/CloudGrid.h"

#include "clouds/CloudSettings.h"

#include <cmath>

namespace firmament {

std::uint32_t packCloudCell(CloudCell cell) {
    return static_cast<std::uint32_t>(cell.i) | (static_cast<std::uint32_t>(cell.j) << 10) | (static_cast<std::uint32_t>(cell.ring) << 20);
}

CloudCell unpackCloudCell(std::uint32_t packed) {
    return {static_cast<int>(packed >> 20), static_cast<int>(packed & 1023u), static_cast<int>((packed >> 10) & 1023u)};
}

CloudGrid::CloudGrid(int rings, int ringDimension, double particleDistance)
    : rings_(rings), dimension_(ringDimension), particleDistance_(particleDistance) {}

std::vector<CloudCell> CloudGrid::cells() const {
    std::vector<CloudCell> cells;
    cells.reserve(static_cast<size_t>(cellCount(rings_, dimension_)));
    const int quarter = dimension_ / 4;
    for (int ring = rings_ - 1; ring >= 0; --ring)
        for (int j = 0; j < dimension_; ++j)
            for (int i = 0; i < dimension_; ++i) {
                // The middle half of an outer ring belongs to the ring inside it.
                const bool inner = ring > 0 && i >= quarter && i < dimension_ - quarter && j >= quarter && j < dimension_ - quarter;
                if (!inner) cells.push_back({ring, i, j});
            }
    return cells;
}

CloudGrid::CloudGrid(const CloudSettings& settings) : CloudGrid(settings.rings, settings.effectiveRingDimension(), settings.particleDistance) {}

double CloudGrid::cellSize(int ring) const { return 2.0 * particleDistance_ / (static_cast<double>(dimension_) * std::ldexp(1.0, rings_ - 1 - ring)); }

glm::dvec2 CloudGrid::centre(glm::dvec2 camera) const {
    const double outer = cellSize(rings_ - 1);
    return {std::floor(camera.x / outer + 0.5) * outer, std::floor(camera.y / outer + 0.5) * outer};
}

glm::dvec2 CloudGrid::cellCentre(CloudCell cell, glm::dvec2 centre) const {
    const double size = cellSize(cell.ring), half = dimension_ / 2;
    return {centre.x + (cell.i - half + 0.5) * size, centre.y + (cell.j - half + 0.5) * size};
}

long long CloudGrid::cellCount(int rings, int ringDimension) {
    const long long d2 = static_cast<long long>(ringDimension) * ringDimension;
    return d2 + static_cast<long long>(rings - 1) * (d2 - d2 / 4);
}

}  // namespace firmament
