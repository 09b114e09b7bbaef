#pragma once
// The index buffer of a clipmap level's grid (ClipmapLayout.h), whose vertices the vertex shader
// places from SV_VertexID alone (no vertex buffer):
//  - (kClipmapCells + 1)^2 grid vertices, row by row: vertex i + j * (cells + 1) at column i, row j;
//  - then 2 * kClipmapCells midpoints of the hole's edge cells, side by side (lowest z, highest x,
//    highest z, lowest x), each where the finer level has a vertex of its boundary. The cells
//    along the hole take them into a fan of three triangles, so the two levels share every
//    vertex of their common edge: no T-junction, a watertight mesh.
// Ten index ranges: the whole grid (the finest level) and the grid less its hole for each of the
// nine hole offsets. Triangles are clockwise seen from above (+y), Direct3D's front faces.
#include "terrain/ClipmapLayout.h"

#include <glm/vec2.hpp>

#include <d3d11.h>
#include <wrl/client.h>

#include <array>
#include <cstdint>
#include <vector>

namespace firmament {

inline constexpr std::uint32_t kClipmapGridVertices = (kClipmapCells + 1) * (kClipmapCells + 1);

// Where vertex `id` stands, in cells from the level's origin, for a hole starting at holeFirst
// (the vertex shader's placement).
glm::dvec2 clipmapVertexCell(std::uint32_t id, glm::ivec2 holeFirst);

struct IndexRange {
    UINT first = 0;
    UINT count = 0;
};

// The indices of every range, and where each range lies: [0..8] holed, offset (dx, dz) at
// (dx + 1) * 3 + (dz + 1); [9] the whole grid.
struct ClipmapIndices {
    std::vector<std::uint32_t> indices;
    std::array<IndexRange, 10> ranges;
};
ClipmapIndices buildClipmapIndices();

class ClipmapMesh {
public:
    explicit ClipmapMesh(ID3D11Device* device);
    void bind(ID3D11DeviceContext* context) const;  // the index buffer and the triangle list topology
    IndexRange whole() const { return ranges_[9]; }
    IndexRange holed(glm::ivec2 offset) const { return ranges_[static_cast<size_t>((offset.x + 1) * 3 + (offset.y + 1))]; }

private:
    Microsoft::WRL::ComPtr<ID3D11Buffer> indices_;
    std::array<IndexRange, 10> ranges_;
};

}  // namespace firmament
