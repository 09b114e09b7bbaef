#include "terrain/ClipmapMesh.h"

#include "gpu/Hresult.h"
#include "terrain/ClipmapLayout.h"

namespace firmament {

glm::dvec2 clipmapVertexCell(std::uint32_t id, glm::ivec2 holeFirst) {
    constexpr std::uint32_t n = kClipmapCells, half = kClipmapCells / 2;
    if (id < kClipmapGridVertices) return {static_cast<double>(id % (n + 1)), static_cast<double>(id / (n + 1))};
    const std::uint32_t k = id - kClipmapGridVertices, side = k / half;
    const double t = (k % half) + 0.5;
    const glm::dvec2 h(holeFirst);
    switch (side) {
        case 0: return {h.x + t, h.y};          // the hole's edge at its lowest z
        case 1: return {h.x + half, h.y + t};   // at its highest x
        case 2: return {h.x + t, h.y + half};   // at its highest z
        default: return {h.x, h.y + t};         // at its lowest x
    }
}

ClipmapIndices buildClipmapIndices() {
    constexpr std::uint32_t n = kClipmapCells, half = kClipmapCells / 2;
    const auto vertex = [](std::uint32_t i, std::uint32_t j) { return i + j * (n + 1); };
    ClipmapIndices mesh;
    for (int variant = 0; variant < 10; ++variant) {
        const bool holed = variant < 9;
        const std::uint32_t hx = holed ? static_cast<std::uint32_t>(holeFirstCell(variant / 3 - 1)) : 0;
        const std::uint32_t hz = holed ? static_cast<std::uint32_t>(holeFirstCell(variant % 3 - 1)) : 0;
        const auto within = [&](std::uint32_t c, std::uint32_t first) { return c >= first && c < first + half; };
        const UINT start = static_cast<UINT>(mesh.indices.size());
        for (std::uint32_t j = 0; j < n; ++j)
            for (std::uint32_t i = 0; i < n; ++i) {
                if (holed && within(i, hx) && within(j, hz)) continue;
                // The cell's corners clockwise seen from +y (x to the right, z up).
                std::uint32_t corners[4] = {vertex(i, j), vertex(i, j + 1), vertex(i + 1, j + 1), vertex(i + 1, j)};
                // A cell along the hole shares an edge with two cells of the finer level, whose
                // middle vertex it takes too: a fan from it, and no T-junction.
                int edge = -1;  // the corner the midpoint follows: 0 left, 1 top, 2 right, 3 bottom edge
                std::uint32_t midpoint = 0;
                if (holed && within(i, hx) && j + 1 == hz) {
                    edge = 1, midpoint = kClipmapGridVertices + 0 * half + (i - hx);
                } else if (holed && within(i, hx) && j == hz + half) {
                    edge = 3, midpoint = kClipmapGridVertices + 2 * half + (i - hx);
                } else if (holed && within(j, hz) && i + 1 == hx) {
                    edge = 2, midpoint = kClipmapGridVertices + 3 * half + (j - hz);
                } else if (holed && within(j, hz) && i == hx + half) {
                    edge = 0, midpoint = kClipmapGridVertices + 1 * half + (j - hz);
                }
                if (edge < 0) {
                    mesh.indices.insert(mesh.indices.end(), {corners[0], corners[1], corners[3], corners[3], corners[1], corners[2]});
                    continue;
                }
                for (int k = 1; k <= 3; ++k)
                    mesh.indices.insert(mesh.indices.end(), {midpoint, corners[(edge + k) % 4], corners[(edge + k + 1) % 4]});
            }
        mesh.ranges[static_cast<size_t>(variant)] = {start, static_cast<UINT>(mesh.indices.size()) - start};
    }
    return mesh;
}

ClipmapMesh::ClipmapMesh(ID3D11Device* device) {
    const ClipmapIndices mesh = buildClipmapIndices();
    ranges_ = mesh.ranges;
    D3D11_BUFFER_DESC desc{};
    desc.ByteWidth = static_cast<UINT>(mesh.indices.size() * sizeof(std::uint32_t));
    desc.Usage = D3D11_USAGE_IMMUTABLE;
    desc.BindFlags = D3D11_BIND_INDEX_BUFFER;
    D3D11_SUBRESOURCE_DATA data{mesh.indices.data(), 0, 0};
    check(device->CreateBuffer(&desc, &data, &indices_), "CreateBuffer (clipmap indices)");
}

void ClipmapMesh::bind(ID3D11DeviceContext* context) const {
    context->IASetIndexBuffer(indices_.Get(), DXGI_FORMAT_R32_UINT, 0);
    context->IASetPrimitiveTopology(D3D11_PRIMITIVE_TOPOLOGY_TRIANGLELIST);
    context->IASetInputLayout(nullptr);
}

}  // namespace firmament
