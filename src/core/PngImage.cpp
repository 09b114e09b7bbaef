#include "core/PngImage.h"

#include "core/Error.h"
#include "core/ImageLimits.h"
#include "core/FileIO.h"

#include <zlib.h>

#include <array>
#include <cstdlib>
#include <cstring>
#include <string>

namespace firmament {

namespace {

constexpr std::array<std::uint8_t, 8> kSignature = {0x89, 'P', 'N', 'G', '\r', '\n', 0x1a, '\n'};

void putBigEndian32(std::vector<std::uint8_t>& out, std::uint32_t value) {
    for (int shift = 24; shift >= 0; shift -= 8) out.push_back(static_cast<std::uint8_t>(value >> shift));
}

std::uint32_t bigEndian32(const std::uint8_t* p) {
    return (std::uint32_t(p[0]) << 24) | (std::uint32_t(p[1]) << 16) | (std::uint32_t(p[2]) << 8) | p[3];
}

void putChunk(std::vector<std::uint8_t>& out, const char type[4], std::span<const std::uint8_t> data) {
    putBigEndian32(out, static_cast<std::uint32_t>(data.size()));
    const size_t typeAt = out.size();
    out.insert(out.end(), type, type + 4);
    out.insert(out.end(), data.begin(), data.end());
    const auto crc = crc32(0, out.data() + typeAt, static_cast<uInt>(4 + data.size()));
    putBigEndian32(out, static_cast<std::uint32_t>(crc));
}

// The Paeth predictor of the PNG specification (section 9.4).
std::uint8_t paeth(int a, int b, int c) {
    const int p = a + b - c;
    const int pa = std::abs(p - a), pb = std::abs(p - b), pc = std::abs(p - c);
    if (pa <= pb && pa <= pc) return static_cast<std::uint8_t>(a);
    return static_cast<std::uint8_t>(pb <= pc ? b : c);
}

}  // namespace

std::vector<std::uint8_t> encodePng(const Rgba8Image& image) {
    if (image.width <= 0 || image.height <= 0 ||
        image.pixels.size() != static_cast<size_t>(image.width) * image.height * 4)
        throw Error("encodePng: image size does not match its pixel data");

    // Every row is stored with filter type 0 (none): simple, and zlib does the rest.
    const size_t rowBytes = static_cast<size_t>(image.width) * 4;
    std::vector<std::uint8_t> raw;
    raw.reserve((rowBytes + 1) * image.height);
    for (int y = 0; y < image.height; ++y) {
        raw.push_back(0);
        const auto* row = image.pixels.data() + y * rowBytes;
        raw.insert(raw.end(), row, row + rowBytes);
    }
    uLongf compressedSize = compressBound(static_cast<uLong>(raw.size()));
    std::vector<std::uint8_t> compressed(compressedSize);
    if (compress2(compressed.data(), &compressedSize, raw.data(), static_cast<uLong>(raw.size()), 6) != Z_OK)
        throw Error("encodePng: zlib compression failed");
    compressed.resize(compressedSize);

    std::vector<std::uint8_t> header;
    putBigEndian32(header, static_cast<std::uint32_t>(image.width));
    putBigEndian32(header, static_cast<std::uint32_t>(image.height));
    header.insert(header.end(), {8, 6, 0, 0, 0});  // 8 bits, RGBA, deflate, no filter set, no interlace

    std::vector<std::uint8_t> out(kSignature.begin(), kSignature.end());
    putChunk(out, "IHDR", header);
    putChunk(out, "IDAT", compressed);
    putChunk(out, "IEND", {});
    return out;
}

Rgba8Image decodePng(std::span<const std::uint8_t> file) {
    if (file.size() < kSignature.size() || std::memcmp(file.data(), kSignature.data(), kSignature.size()) != 0)
        throw Error("not a PNG file (bad signature)");

    Rgba8Image image;
    int channels = 0;
    std::vector<std::uint8_t> compressed;
    for (size_t at = kSignature.size(); at + 12 <= file.size();) {
        const std::uint32_t length = bigEndian32(&file[at]);
        if (at + 12 + length > file.size()) throw Error("PNG chunk runs past the end of the file");
        const std::string type(reinterpret_cast<const char*>(&file[at + 4]), 4);
        const std::uint8_t* data = &file[at + 8];
        if (type == "IHDR") {
            if (length != 13) throw Error("PNG IHDR chunk has the wrong size");
            image.width = static_cast<int>(bigEndian32(data));
            image.height = static_cast<int>(bigEndian32(data + 4));
            const int bitDepth = data[8], colourType = data[9], interlace = data[12];
            if (bitDepth != 8 || (colourType != 6 && colourType != 2) || interlace != 0)
                throw Error("unsupported PNG format (only 8-bit RGB/RGBA, not interlaced)");
            channels = colourType == 6 ? 4 : 3;
        } else if (type == "IDAT") {
            compressed.insert(compressed.end(), data, data + length);
        } else if (type == "IEND") {
            break;
        }
        at += 12 + length;
    }
    if (channels == 0) throw Error("PNG has no valid IHDR chunk");
    if (const std::string why = checkImageSize(image.width, image.height); !why.empty()) throw Error("PNG image: " + why);

    const size_t stride = static_cast<size_t>(image.width) * channels;
    // Deflate expands at most 1032 times: a file too short for its rows is refused before its
    // rows are allocated (a 30-byte file once asked for 11 GB).
    if ((stride + 1) * image.height / 1032 > compressed.size()) throw Error("PNG image data is too short for its size");
    std::vector<std::uint8_t> raw((stride + 1) * image.height);
    uLongf rawSize = static_cast<uLongf>(raw.size());
    if (uncompress(raw.data(), &rawSize, compressed.data(), static_cast<uLong>(compressed.size())) != Z_OK ||
        rawSize != raw.size())
        throw Error("PNG image data is corrupt");

    // Undo the per-row filters (PNG specification, section 9.2), in place.
    std::vector<std::uint8_t> previous(stride, 0);
    image.pixels.resize(static_cast<size_t>(image.width) * image.height * 4);
    for (int y = 0; y < image.height; ++y) {
        std::uint8_t* row = &raw[y * (stride + 1) + 1];
        const int filter = row[-1];
        for (size_t i = 0; i < stride; ++i) {
            const int left = i >= static_cast<size_t>(channels) ? row[i - channels] : 0;
            const int up = previous[i];
            const int upLeft = i >= static_cast<size_t>(channels) ? previous[i - channels] : 0;
            int predictor = 0;
            switch (filter) {
                case 0: predictor = 0; break;
                case 1: predictor = left; break;
                case 2: predictor = up; break;
                case 3: predictor = (left + up) / 2; break;
                case 4: predictor = paeth(left, up, upLeft); break;
                default: throw Error("PNG row has an unknown filter type");
            }
            row[i] = static_cast<std::uint8_t>(row[i] + predictor);
        }
        std::memcpy(previous.data(), row, stride);
        for (int x = 0; x < image.width; ++x) {
            std::uint8_t* out = &image.pixels[(static_cast<size_t>(y) * image.width + x) * 4];
            for (int c = 0; c < 3; ++c) out[c] = row[x * channels + c];
            out[3] = channels == 4 ? row[x * channels + 3] : 255;
        }
    }
    return image;
}

void writePng(const std::filesystem::path& path, const Rgba8Image& image) {
    writeFileBytes(path, encodePng(image));
}

Rgba8Image readPng(const std::filesystem::path& path) {
    const auto bytes = readFileBytes(path);
    try {
        return decodePng(bytes);
    } catch (const Error& e) {
        throw Error("'" + path.string() + "': " + e.what());
    }
}

}  // namespace firmament
