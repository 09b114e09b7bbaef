#pragma once
// The index buffer of a clipmap level's grid (ClipmapLayout.h): (kClipmapCells + 1)^2 vertices,
// numbered row by row (vertex i + j * (cells + 1) at column i, row j), which the vertex shader
// places from SV_VertexID alone, so there is no vertex buffer. Ten index ranges: the whole grid
// (the finest level) and the grid less its hole for each of the nine hole offsets. Triangles are
// clockwise seen from above (+y), Direct3D's front faces.
#include <glm/vec2.hpp>

#include <d3d11.h>
#include <wrl/client.h>

#include <array>
#include <cstdint>
#include <vector>

namespace firmament {

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
