#include "gpu/Readback.h"

#include "core/Error.h"
#include "gpu/Hresult.h"

#include <wrl/client.h>

#include <cstring>

namespace firmament {

using Microsoft::WRL::ComPtr;

int bytesPerPixel(DXGI_FORMAT format) {
    switch (format) {
        case DXGI_FORMAT_R8G8B8A8_UNORM:
        case DXGI_FORMAT_R8G8B8A8_UNORM_SRGB:
        case DXGI_FORMAT_B8G8R8A8_UNORM:
        case DXGI_FORMAT_R32_FLOAT:
        case DXGI_FORMAT_R32_UINT:
        case DXGI_FORMAT_R16G16_UINT:
        case DXGI_FORMAT_R16G16_UNORM:
        case DXGI_FORMAT_R32_TYPELESS: return 4;
        case DXGI_FORMAT_R16G16B16A16_FLOAT:
        case DXGI_FORMAT_R32G32_FLOAT: return 8;
        case DXGI_FORMAT_R32G32B32A32_FLOAT: return 16;
        default: throw Error("read-back of DXGI format " + std::to_string(static_cast<int>(format)) + " is not supported");
    }
}

namespace {

// `desc` made the description of a staging copy the CPU reads.
template <typename Description>
Description staging(Description desc) {
    desc.Usage = D3D11_USAGE_STAGING;
    desc.BindFlags = 0;
    desc.CPUAccessFlags = D3D11_CPU_ACCESS_READ;
    desc.MiscFlags = 0;
    return desc;
}

// Subresource 0 of `source` copied into `copy` (its staging twin), mapped, and its `slices` x
// `rows` rows of `rowBytes` each copied out tightly packed (the mapping's pitches dropped).
std::vector<std::uint8_t> readRows(ID3D11DeviceContext* context, ID3D11Resource* copy, ID3D11Resource* source, size_t rowBytes, int rows,
                                   int slices, const char* what) {
    context->CopySubresourceRegion(copy, 0, 0, 0, 0, source, 0, nullptr);
    D3D11_MAPPED_SUBRESOURCE mapped{};
    check(context->Map(copy, 0, D3D11_MAP_READ, 0, &mapped), what);
    std::vector<std::uint8_t> bytes(rowBytes * rows * slices);
    const auto* from = static_cast<const std::uint8_t*>(mapped.pData);
    for (int z = 0; z < slices; ++z)
        for (int y = 0; y < rows; ++y)
            std::memcpy(bytes.data() + (static_cast<size_t>(z) * rows + y) * rowBytes, from + z * mapped.DepthPitch + y * mapped.RowPitch, rowBytes);
    context->Unmap(copy, 0);
    return bytes;
}

}  // namespace

ReadbackImage readTexture2D(ID3D11Device* device, ID3D11DeviceContext* context, ID3D11Texture2D* texture) {
    D3D11_TEXTURE2D_DESC desc{};
    texture->GetDesc(&desc);
    ReadbackImage image;
    image.width = static_cast<int>(desc.Width);
    image.height = static_cast<int>(desc.Height);
    image.bytesPerPixel = bytesPerPixel(desc.Format);
    desc.MipLevels = 1;
    desc.ArraySize = 1;
    desc.SampleDesc = {1, 0};
    desc = staging(desc);
    ComPtr<ID3D11Texture2D> copy;
    check(device->CreateTexture2D(&desc, nullptr, &copy), "CreateTexture2D (staging)");
    image.bytes = readRows(context, copy.Get(), texture, static_cast<size_t>(image.width) * image.bytesPerPixel, image.height, 1,
                           "Map (texture read-back)");
    return image;
}

ReadbackVolume readTexture3D(ID3D11Device* device, ID3D11DeviceContext* context, ID3D11Texture3D* texture) {
    D3D11_TEXTURE3D_DESC desc{};
    texture->GetDesc(&desc);
    ReadbackVolume volume;
    volume.width = static_cast<int>(desc.Width);
    volume.height = static_cast<int>(desc.Height);
    volume.depth = static_cast<int>(desc.Depth);
    volume.bytesPerPixel = bytesPerPixel(desc.Format);
    desc.MipLevels = 1;
    desc = staging(desc);
    ComPtr<ID3D11Texture3D> copy;
    check(device->CreateTexture3D(&desc, nullptr, &copy), "CreateTexture3D (staging)");
    volume.bytes = readRows(context, copy.Get(), texture, static_cast<size_t>(volume.width) * volume.bytesPerPixel, volume.height, volume.depth,
                            "Map (volume read-back)");
    return volume;
}

std::vector<std::uint8_t> readBuffer(ID3D11Device* device, ID3D11DeviceContext* context, ID3D11Buffer* buffer) {
    D3D11_BUFFER_DESC desc{};
    buffer->GetDesc(&desc);
    desc = staging(desc);
    desc.StructureByteStride = 0;
    ComPtr<ID3D11Buffer> copy;
    check(device->CreateBuffer(&desc, nullptr, &copy), "CreateBuffer (staging)");
    return readRows(context, copy.Get(), buffer, desc.ByteWidth, 1, 1, "Map (buffer read-back)");
}

}  // namespace firmament
