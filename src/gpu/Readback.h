#pragma once
// Copies GPU resources into CPU memory through staging resources (blocking: for captures,
// tests and cache writes, never in the frame loop).
#include <d3d11.h>

#include <cstdint>
#include <vector>

namespace firmament {

struct ReadbackImage {
    int width = 0;
    int height = 0;
    int bytesPerPixel = 0;
    std::vector<std::uint8_t> bytes;  // tightly packed rows, top row first
};

int bytesPerPixel(DXGI_FORMAT format);  // throws Error for formats the program does not read back

ReadbackImage readTexture2D(ID3D11Device* device, ID3D11DeviceContext* context, ID3D11Texture2D* texture);

struct ReadbackVolume {
    int width = 0;
    int height = 0;
    int depth = 0;
    int bytesPerPixel = 0;
    std::vector<std::uint8_t> bytes;  // tightly packed: x fastest, then y, then z
};

ReadbackVolume readTexture3D(ID3D11Device* device, ID3D11DeviceContext* context, ID3D11Texture3D* texture);
std::vector<std::uint8_t> readBuffer(ID3D11Device* device, ID3D11DeviceContext* context, ID3D11Buffer* buffer);

}  // namespace firmament
