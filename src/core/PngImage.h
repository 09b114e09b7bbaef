#pragma once
// 8-bit RGBA PNG files: writing captures and reading them back in tests (golden images).
// Only what Firmament writes is read: 8-bit RGB or RGBA, not interlaced.
#include <cstdint>
#include <filesystem>
#include <span>
#include <vector>

namespace firmament {

struct Rgba8Image {
    int width = 0;
    int height = 0;
    std::vector<std::uint8_t> pixels;  // row-major, top row first, 4 bytes per pixel

    const std::uint8_t* pixel(int x, int y) const { return &pixels[(static_cast<size_t>(y) * width + x) * 4]; }
};

std::vector<std::uint8_t> encodePng(const Rgba8Image& image);
Rgba8Image decodePng(std::span<const std::uint8_t> file);  // throws Error on a bad file

void writePng(const std::filesystem::path& path, const Rgba8Image& image);  // throws Error
Rgba8Image readPng(const std::filesystem::path& path);                       // throws Error

}  // namespace firmament
