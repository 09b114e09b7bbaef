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
    desc.Usage = D3D11_USAGE_STAGING;
    desc.BindFlags = 0;
    desc.CPUAccessFlags = D3D11_CPU_ACCESS_READ;
    desc.MiscFlags = 0;
    ComPtr<ID3D11Texture2D> staging;
    check(device->CreateTexture2D(&desc, nullptr, &staging), "CreateTexture2D (staging)");
    context->CopySubresourceRegion(staging.Get(), 0, 0, 0, 0, texture, 0, nullptr);

    D3D11_MAPPED_SUBRESOURCE mapped{};
    check(context->Map(staging.Get(), 0, D3D11_MAP_READ, 0, &mapped), "Map (texture read-back)");
    const size_t rowBytes = static_cast<size_t>(image.width) * image.bytesPerPixel;
    image.bytes.resize(rowBytes * image.height);
    for (int y = 0; y < image.height; ++y)
        std::memcpy(image.bytes.data() + y * rowBytes, static_cast<const std::uint8_t*>(mapped.pData) + y * mapped.RowPitch,
                    rowBytes);
    context->Unmap(staging.Get(), 0);
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
    desc.Usage = D3D11_USAGE_STAGING;
    desc.BindFlags = 0;
    desc.CPUAccessFlags = D3D11_CPU_ACCESS_READ;
    desc.MiscFlags = 0;
    ComPtr<ID3D11Texture3D> staging;
    check(device->CreateTexture3D(&desc, nullptr, &staging), "CreateTexture3D (staging)");
    context->CopySubresourceRegion(staging.Get(), 0, 0, 0, 0, texture, 0, nullptr);

    D3D11_MAPPED_SUBRESOURCE mapped{};
    check(context->Map(staging.Get(), 0, D3D11_MAP_READ, 0, &mapped), "Map (volume read-back)");
    const size_t rowBytes = static_cast<size_t>(volume.width) * volume.bytesPerPixel;
    volume.bytes.resize(rowBytes * volume.height * volume.depth);
    for (int z = 0; z < volume.depth; ++z)
        for (int y = 0; y < volume.height; ++y)
            std::memcpy(volume.bytes.data() + (static_cast<size_t>(z) * volume.height + y) * rowBytes,
                        static_cast<const std::uint8_t*>(mapped.pData) + z * mapped.DepthPitch + y * mapped.RowPitch, rowBytes);
    context->Unmap(staging.Get(), 0);
    return volume;
}

std::vector<std::uint8_t> readBuffer(ID3D11Device* device, ID3D11DeviceContext* context, ID3D11Buffer* buffer) {
    D3D11_BUFFER_DESC desc{};
    buffer->GetDesc(&desc);
    desc.Usage = D3D11_USAGE_STAGING;
    desc.BindFlags = 0;
    desc.CPUAccessFlags = D3D11_CPU_ACCESS_READ;
    desc.MiscFlags = 0;
    desc.StructureByteStride = 0;
    ComPtr<ID3D11Buffer> staging;
    check(device->CreateBuffer(&desc, nullptr, &staging), "CreateBuffer (staging)");
    context->CopyResource(staging.Get(), buffer);

    D3D11_MAPPED_SUBRESOURCE mapped{};
    check(context->Map(staging.Get(), 0, D3D11_MAP_READ, 0, &mapped), "Map (buffer read-back)");
    std::vector<std::uint8_t> bytes(desc.ByteWidth);
    std::memcpy(bytes.data(), mapped.pData, bytes.size());
    context->Unmap(staging.Get(), 0);
    return bytes;
}

}  // namespace firmament
