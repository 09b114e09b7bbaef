#pragma once
// Half-float RGBA OpenEXR files with typed header attributes: HDR captures, and later the
// scattering look-up tables. Self-describing files: whatever a reader needs to interpret the
// pixels (resolution, matrices, settings, version) travels in the header.
#include <glm/glm.hpp>

#include <cstdint>
#include <filesystem>
#include <map>
#include <span>
#include <string>
#include <variant>
#include <vector>

namespace firmament {

struct HalfRgbaImage {
    int width = 0;
    int height = 0;
    std::vector<std::uint16_t> halfBits;  // IEEE 754 binary16 bits, RGBA, top row first
};

// A header attribute. Matrices are stored as Imath M44f, which multiplies row vectors:
// element [i][j] of the file's matrix is glm's m[i][j] (column i, row j), so v * M in
// Imath equals M * v in glm.
using ExrAttribute = std::variant<std::string, float, int, glm::vec3, glm::ivec2, glm::mat4>;
using ExrAttributes = std::map<std::string, ExrAttribute>;

struct ExrFile {
    HalfRgbaImage image;
    ExrAttributes attributes;  // only the attributes of the types above; others are skipped
};

// 32-bit float RGBA, for look-up tables whose values exceed the half range.
struct FloatRgbaImage {
    int width = 0;
    int height = 0;
    std::vector<float> rgba;  // top row first
};

struct FloatExrFile {
    FloatRgbaImage image;
    ExrAttributes attributes;
};

// 32-bit float, one channel "Y": height fields.
struct FloatImage {
    int width = 0;
    int height = 0;
    std::vector<float> values;  // top row first
};

struct FloatImageFile {
    FloatImage image;
    ExrAttributes attributes;
};

void writeExr(const std::filesystem::path& path, const HalfRgbaImage& image, const ExrAttributes& attributes);
void writeExr(const std::filesystem::path& path, const FloatRgbaImage& image, const ExrAttributes& attributes);
ExrFile readExr(const std::filesystem::path& path);            // throws Error
FloatExrFile readFloatExr(const std::filesystem::path& path);  // any pixel type, converted; throws Error
void writeExr(const std::filesystem::path& path, const FloatImage& image, const ExrAttributes& attributes);
FloatImageFile readFloatChannelExr(const std::filesystem::path& path);  // channel "Y"; throws Error when it is missing

// The same readers over a file's bytes; `name` stands for the file in the messages. Throws Error.
ExrFile decodeExr(std::span<const std::uint8_t> bytes, const std::string& name);
FloatExrFile decodeFloatExr(std::span<const std::uint8_t> bytes, const std::string& name);
FloatImageFile decodeFloatChannelExr(std::span<const std::uint8_t> bytes, const std::string& name);

}  // namespace firmament
