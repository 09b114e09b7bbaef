// PNG encoding and decoding: round trips, an independent test vector that uses every row
// filter (our encoder writes only filter 0), and corrupt input reported as Error.
#include "core/Error.h"
#include "core/PngImage.h"

#include <gtest/gtest.h>

#include <array>
#include <random>

namespace firmament {
namespace {

// A 4 x 5 RGBA image encoded by a separate Python implementation with row filters
// 0 (none), 1 (sub), 2 (up), 3 (average), 4 (Paeth) on rows 0..4. Pixel (x, y) is
// ((37x + 11y) % 256, (5x + 71y) % 256, (255 - 23x - 3y) % 256, (128 + x + 9y) % 256).
constexpr std::array<std::uint8_t, 118> kFilteredPng = {
    0x89, 0x50, 0x4e, 0x47, 0x0d, 0x0a, 0x1a, 0x0a, 0x00, 0x00, 0x00, 0x0d, 0x49, 0x48, 0x44, 0x52, 0x00, 0x00,
    0x00, 0x04, 0x00, 0x00, 0x00, 0x05, 0x08, 0x06, 0x00, 0x00, 0x00, 0x62, 0xad, 0x4d, 0xdb, 0x00, 0x00, 0x00,
    0x3d, 0x49, 0x44, 0x41, 0x54, 0x78, 0xda, 0x63, 0x60, 0x60, 0xf8, 0xdf, 0xa0, 0xca, 0xfa, 0xa2, 0xd1, 0x8b,
    0xeb, 0x62, 0x53, 0x3e, 0xff, 0xae, 0x66, 0x46, 0x6e, 0xf7, 0x3f, 0x9d, 0xaa, 0xac, 0x2f, 0x19, 0x61, 0x98,
    0x89, 0xdb, 0xfd, 0x2f, 0x27, 0x32, 0x66, 0x16, 0xeb, 0xab, 0x0a, 0x92, 0x50, 0xfb, 0xcc, 0x0a, 0xc3, 0x2c,
    0x60, 0x19, 0xd6, 0xbf, 0x8c, 0x30, 0x0c, 0x00, 0xa6, 0x41, 0x1a, 0x86, 0x91, 0xfe, 0xc9, 0xb7, 0x00, 0x00,
    0x00, 0x00, 0x49, 0x45, 0x4e, 0x44, 0xae, 0x42, 0x60, 0x82};

Rgba8Image randomImage(int width, int height, unsigned seed) {
    std::mt19937 random(seed);
    Rgba8Image image{width, height, std::vector<std::uint8_t>(static_cast<size_t>(width) * height * 4)};
    for (auto& byte : image.pixels) byte = static_cast<std::uint8_t>(random() & 0xff);
    return image;
}

TEST(PngImage, EncodeDecodeRoundTripIsExact) {
    const Rgba8Image image = randomImage(37, 19, 7);
    const Rgba8Image decoded = decodePng(encodePng(image));
    EXPECT_EQ(decoded.width, 37);
    EXPECT_EQ(decoded.height, 19);
    EXPECT_EQ(decoded.pixels, image.pixels);
}

TEST(PngImage, DecodesEveryRowFilterOfAnIndependentEncoder) {
    const Rgba8Image image = decodePng(kFilteredPng);
    ASSERT_EQ(image.width, 4);
    ASSERT_EQ(image.height, 5);
    for (int y = 0; y < 5; ++y)
        for (int x = 0; x < 4; ++x) {
            const std::uint8_t* p = image.pixel(x, y);
            EXPECT_EQ(p[0], (37 * x + 11 * y) % 256) << x << "," << y;
            EXPECT_EQ(p[1], (5 * x + 71 * y) % 256) << x << "," << y;
            EXPECT_EQ(p[2], ((255 - 23 * x - 3 * y) % 256 + 256) % 256) << x << "," << y;
            EXPECT_EQ(p[3], (128 + x + 9 * y) % 256) << x << "," << y;
        }
}

TEST(PngImage, CorruptFilesAreReportedAsErrors) {
    std::vector<std::uint8_t> file(kFilteredPng.begin(), kFilteredPng.end());
    EXPECT_THROW(decodePng(std::vector<std::uint8_t>(file.begin(), file.begin() + 20)), Error);  // truncated
    file[1] = 'X';
    EXPECT_THROW(decodePng(file), Error);  // bad signature
    std::vector<std::uint8_t> badData(kFilteredPng.begin(), kFilteredPng.end());
    badData[50] ^= 0xff;  // inside the compressed image data
    EXPECT_THROW(decodePng(badData), Error);
}

TEST(PngImage, WriteAndReadFile) {
    const auto path = std::filesystem::temp_directory_path() / "firmament-png-test.png";
    const Rgba8Image image = randomImage(8, 8, 3);
    writePng(path, image);
    EXPECT_EQ(readPng(path).pixels, image.pixels);
    std::filesystem::remove(path);
    EXPECT_THROW(readPng(path), Error);
}

// Found by fuzzing (tests/fuzz/regressions/png): a header that asks for gigabytes is refused
// before the rows are allocated.
TEST(PngImage, AHeaderAskingForMoreThanTheFileHoldsIsRefused) {
    const std::vector<std::uint8_t> valid = encodePng(Rgba8Image{3, 2, std::vector<std::uint8_t>(24, 7)});
    const auto withSize = [&](std::uint32_t width, std::uint32_t height) {
        std::vector<std::uint8_t> bytes = valid;
        for (int i = 0; i < 4; ++i) {  // IHDR's width and height, big-endian, after the signature and chunk head
            bytes[16 + i] = static_cast<std::uint8_t>(width >> (24 - 8 * i));
            bytes[20 + i] = static_cast<std::uint8_t>(height >> (24 - 8 * i));
        }
        return bytes;
    };
    const auto refusal = [](const std::vector<std::uint8_t>& bytes) {
        try {
            decodePng(bytes);
        } catch (const Error& e) {
            return std::string(e.what());
        }
        return std::string("decoded");
    };
    EXPECT_NE(refusal(withSize(0x53000003u, 2)).find("exceeds 16384 pixels a side"), std::string::npos);
    EXPECT_NE(refusal(withSize(16000, 16000)).find("too short for its size"), std::string::npos);
    EXPECT_EQ(decodePng(withSize(3, 2)).pixels.size(), 24u);
}

}  // namespace
}  // namespace firmament
