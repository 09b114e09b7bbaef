#pragma once
// The clouds' cell grid (Yusov 2014, "Particle generation"): square rings of cells centred on
// the camera, each ring's cells twice the size of the inner ring's. Ring 0 is a full square of
// D x D cells; every outer ring is a D x D square whose middle D/2 x D/2 cells are left out,
// because the inner ring covers them exactly. The outer ring's half-width is the particle
// distance, so its cells measure 2 * distance / D and ring r's 2 * distance / (D * 2^(N-1-r)).
//
// The whole grid is centred on the camera snapped to the outer ring's cells, so every ring
// moves in whole cells of its own (and of the outer ring): a cell keeps its place in the world
// while the camera moves, and the clouds do not swim. The cells' places on the planet are the
// plane's, lifted to the cloud layer's sphere (docs/clouds.md, "Cell grid").
#include <glm/vec2.hpp>

#include <cstdint>
#include <vector>

namespace firmament {

struct CloudSettings;

struct CloudCell {
    int ring = 0;
    int i = 0;  // column (along x) within the ring's D x D square
    int j = 0;  // row (along z)
};

// Cells are listed for the GPU packed into one uint: i, j (10 bits each), ring (4 bits).
std::uint32_t packCloudCell(CloudCell cell);
CloudCell unpackCloudCell(std::uint32_t packed);

class CloudGrid {
public:
    CloudGrid(int rings, int ringDimension, double particleDistance);
    explicit CloudGrid(const CloudSettings& settings);

    int rings() const { return rings_; }
    int dimension() const { return dimension_; }
    // Edge of ring r's cells (m).
    double cellSize(int ring) const;
    // Every cell, outer ring first, row by row: the order of the GPU's cell list.
    std::vector<CloudCell> cells() const;
    // The grid's centre (x, z): the camera's (x, z) snapped to the outer ring's cells.
    glm::dvec2 centre(glm::dvec2 camera) const;
    // The middle of a cell on the plane (x, z), for a grid centred at `centre`.
    glm::dvec2 cellCentre(CloudCell cell, glm::dvec2 centre) const;
    // Cells of ring 0 (D^2) plus (N - 1) outer rings of 3 D^2 / 4.
    static long long cellCount(int rings, int ringDimension);

private:
    int rings_;
    int dimension_;
    double particleDistance_;
};

}  // namespace firmament
