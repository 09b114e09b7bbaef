// OpenEXR writing and reading: pixel values bit for bit and every header attribute type.
#include "core/Error.h"
#include "core/ExrImage.h"
#include "core/FileIO.h"

#include <Imath/half.h>
#include <algorithm>
#include <cstring>
#include <functional>
#include <gtest/gtest.h>

namespace firmament {
namespace {

std::filesystem::path tempPath(const char* name) { return std::filesystem::temp_directory_path() / name; }

HalfRgbaImage rampImage(int width, int height) {
    HalfRgbaImage image{width, height, {}};
    for (int y = 0; y < height; ++y)
        for (int x = 0; x < width; ++x) {
            // HDR values over many octaves, negative and zero included.
            const float values[4] = {static_cast<float>(x) * 37.5f, std::ldexp(1.0f, y - 8), -0.25f * x, y == 0 ? 0.0f : 1.0f};
            for (float v : values) image.halfBits.push_back(Imath::half(v).bits());
        }
    return image;
}

TEST(ExrImage, PixelsAndAttributesRoundTrip) {
    const auto path = tempPath("firmament-exr-test.exr");
    const HalfRgbaImage image = rampImage(13, 11);
    glm::mat4 matrix(0.0f);
    for (int i = 0; i < 16; ++i) matrix[i / 4][i % 4] = static_cast<float>(i) - 7.5f;
    const ExrAttributes attributes{
        {"test.text", std::string("line one\nline two = 2")},
        {"test.float", 0.18f},
        {"test.int", -42},
        {"test.vector", glm::vec3(0.25f, -1.0f, 3.5f)},
        {"test.size", glm::ivec2(13, 11)},
        {"test.matrix", matrix},
    };
    writeExr(path, image, attributes);
    const ExrFile file = readExr(path);
    std::filesystem::remove(path);

    EXPECT_EQ(file.image.width, 13);
    EXPECT_EQ(file.image.height, 11);
    EXPECT_EQ(file.image.halfBits, image.halfBits);
    for (const auto& [name, value] : attributes) {
        ASSERT_TRUE(file.attributes.count(name)) << name;
        EXPECT_EQ(file.attributes.at(name), value) << name;
    }
    // The matrix keeps glm's element order (m[column][row]).
    EXPECT_EQ(std::get<glm::mat4>(file.attributes.at("test.matrix"))[2][3], 11.0f - 7.5f);
}

TEST(ExrImage, MissingAndCorruptFilesAreErrorsNamingThePath) {
    const auto missing = tempPath("firmament-no-such-file.exr");
    try {
        readExr(missing);
        FAIL() << "no error for a missing file";
    } catch (const Error& e) {
        EXPECT_NE(std::string(e.what()).find("firmament-no-such-file.exr"), std::string::npos) << e.what();
    }

    const auto corrupt = tempPath("firmament-corrupt.exr");
    writeExr(corrupt, rampImage(4, 4), {});
    auto bytes = readFileBytes(corrupt);
    bytes.resize(bytes.size() / 2);
    writeFileBytes(corrupt, bytes);
    EXPECT_THROW(readExr(corrupt), Error);
    std::filesystem::remove(corrupt);
}

TEST(ExrImage, ImageSizeMismatchIsRejected) {
    HalfRgbaImage image = rampImage(4, 4);
    image.halfBits.pop_back();
    EXPECT_THROW(writeExr(tempPath("firmament-bad.exr"), image, {}), Error);
}

// 32-bit float images keep values the half type cannot hold (net densities of 1e6 and more)
// bit for bit, and the half reader's files read back through the float reader.
TEST(ExrImage, FloatPixelsRoundTripBitForBit) {
    const auto path = tempPath("firmament-exr-float-test.exr");
    FloatRgbaImage image{7, 5, {}};
    for (int i = 0; i < 7 * 5 * 4; ++i) image.rgba.push_back(std::ldexp(1.0f + 0.001f * static_cast<float>(i), i % 60 - 20) * (i % 3 ? 1.0f : -1.0f));
    writeExr(path, image, {{"test.key", std::string("abc")}});
    const FloatExrFile file = readFloatExr(path);
    std::filesystem::remove(path);
    ASSERT_EQ(file.image.width, 7);
    ASSERT_EQ(file.image.height, 5);
    EXPECT_EQ(file.image.rgba, image.rgba);
    EXPECT_EQ(std::get<std::string>(file.attributes.at("test.key")), "abc");

    const auto halfPath = tempPath("firmament-exr-half-as-float.exr");
    writeExr(halfPath, rampImage(4, 3), {});
    const FloatExrFile widened = readFloatExr(halfPath);
    std::filesystem::remove(halfPath);
    EXPECT_EQ(widened.image.rgba[4 * 4 + 1], std::ldexp(1.0f, 1 - 8));  // pixel (0, 1), green
}

// One float channel "Y" (height fields): bit-exact round trip, and a file without "Y" (an RGBA
// capture) refused with a message naming the path and the channel.
TEST(ExrImage, SingleChannelFloatRoundTripsAndRefusesFilesWithoutIt) {
    const auto path = tempPath("firmament-exr-y-test.exr");
    FloatImage image{6, 4, {}};
    for (int i = 0; i < 6 * 4; ++i) image.values.push_back(std::ldexp(1.0f + 0.01f * static_cast<float>(i), i % 30 - 10));
    writeExr(path, image, {{"test.key", std::string("heights")}});
    const FloatImageFile file = readFloatChannelExr(path);
    std::filesystem::remove(path);
    ASSERT_EQ(file.image.width, 6);
    ASSERT_EQ(file.image.height, 4);
    EXPECT_EQ(file.image.values, image.values);
    EXPECT_EQ(std::get<std::string>(file.attributes.at("test.key")), "heights");
    EXPECT_THROW(writeExr(path, FloatImage{6, 4, std::vector<float>(5)}, {}), Error);

    const auto rgbaPath = tempPath("firmament-exr-rgba-not-y.exr");
    writeExr(rgbaPath, rampImage(4, 3), {});
    try {
        readFloatChannelExr(rgbaPath);
        ADD_FAILURE() << "an RGBA file read as a height field";
    } catch (const Error& e) {
        EXPECT_NE(std::string(e.what()).find("firmament-exr-rgba-not-y.exr"), std::string::npos) << e.what();
        EXPECT_NE(std::string(e.what()).find("no channel Y"), std::string::npos) << e.what();
    }
    std::filesystem::remove(rgbaPath);
}

// Found by fuzzing (tests/fuzz/regressions/exr_table): a header whose data window asks for more
// pixels than any file holds is refused before the pixels are allocated, naming the file.
TEST(ExrImage, ADataWindowLargerThanTheFileCouldHoldIsRefused) {
    const auto path = tempPath("firmament-exr-window.exr");
    writeExr(path, FloatImage{4, 4, std::vector<float>(16, 1.0f)}, {});
    const std::vector<std::uint8_t> valid = readFileBytes(path);
    std::filesystem::remove(path);
    // The attribute is "dataWindow\0box2i\0", its size (16), then min.x, min.y, max.x, max.y.
    const std::string name("dataWindow\0box2i\0", 17);
    const auto at = std::search(valid.begin(), valid.end(), name.begin(), name.end());
    ASSERT_NE(at, valid.end());
    const size_t maxX = static_cast<size_t>(at - valid.begin()) + name.size() + 4 + 8;
    const auto withMax = [&](std::int32_t x, std::int32_t y) {
        std::vector<std::uint8_t> bytes = valid;
        std::memcpy(&bytes[maxX], &x, 4);  // little-endian, as EXR is and as this machine is
        std::memcpy(&bytes[maxX + 4], &y, 4);
        return bytes;
    };
    const auto refusal = [](const std::vector<std::uint8_t>& bytes) {
        try {
            decodeFloatChannelExr(bytes, "heights.exr");
        } catch (const Error& e) {
            return std::string(e.what());
        }
        return std::string("decoded");
    };
    const std::string wide = refusal(withMax(200000, 3));
    EXPECT_NE(wide.find("heights.exr"), std::string::npos) << wide;
    EXPECT_NE(wide.find("exceeds 16384 pixels a side"), std::string::npos) << wide;
    // Within the side limit but far more than the file holds: OpenEXR 3.4 (the portable build)
    // reads the header and leaves it to this check; OpenEXR 3.1 (the MinGW build) already fails
    // reading the offsets of 16,000 rows. Either way it is refused before any pixel is allocated.
    const std::string big = refusal(withMax(15999, 15999));
    EXPECT_NE(big.find("heights.exr"), std::string::npos) << big;
    EXPECT_NE(big, "decoded");
#ifndef _WIN32
    EXPECT_NE(big.find("is too large for a file of"), std::string::npos) << big;
#endif
    EXPECT_EQ(decodeFloatChannelExr(withMax(3, 3), "heights.exr").image.values.size(), 16u);  // the patch itself is sound

    // A window 2314 pixels wide far from the origin (y from 151587081): its pixels' addresses are
    // computed in 64 bits (UndefinedBehaviorSanitizer in the portable build reports int overflow
    // otherwise).
    std::vector<std::uint8_t> far = withMax(2313, 151587081 + 3);
    const std::int32_t minY = 151587081;
    std::memcpy(&far[maxX - 4], &minY, 4);
    for (const auto& decode : {std::function<void()>([&] { decodeFloatChannelExr(far, "far.exr"); }),
                               std::function<void()>([&] { decodeExr(far, "far.exr"); })}) {
        try {
            decode();
        } catch (const Error&) {
        }  // OpenEXR finds the chunks' rows do not match; what matters is no overflow on the way
    }
}

}  // namespace
}  // namespace firmament
