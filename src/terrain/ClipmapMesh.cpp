#include "terrain/ClipmapMesh.h"

#include "gpu/Hresult.h"
#include "terrain/ClipmapLayout.h"

namespace firmament {

ClipmapIndices buildClipmapIndices() {
    constexpr std::uint32_t n = kClipmapCells;
    const auto vertex = [](std::uint32_t i, std::uint32_t j) { return i + j * (n + 1); };
    const auto addCell = [&](std::vector<std::uint32_t>& out, std::uint32_t i, std::uint32_t j) {
        // Seen from +y, x to the right and z up: (0,0) -> (0,1) -> (1,0) turns clockwise.
        out.insert(out.end(), {vertex(i, j), vertex(i, j + 1), vertex(i + 1, j), vertex(i + 1, j), vertex(i, j + 1), vertex(i + 1, j + 1)});
    };
    ClipmapIndices mesh;
    for (int variant = 0; variant < 10; ++variant) {
        const bool holed = variant < 9;
        const int first = holed ? holeFirstCell(variant / 3 - 1) : 0, firstZ = holed ? holeFirstCell(variant % 3 - 1) : 0;
        const auto inHole = [&](int c, int start) { return holed && c >= start && c < start + kClipmapCells / 2; };
        const UINT start = static_cast<UINT>(mesh.indices.size());
        for (std::uint32_t j = 0; j < n; ++j)
            for (std::uint32_t i = 0; i < n; ++i)
                if (!(inHole(static_cast<int>(i), first) && inHole(static_cast<int>(j), firstZ))) addCell(mesh.indices, i, j);
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
