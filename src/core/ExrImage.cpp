#include "core/ExrImage.h"

#include "core/Error.h"
#include "core/FileIO.h"
#include "core/ImageLimits.h"

#include <ImfChannelList.h>
#include <ImfFloatAttribute.h>
#include <ImfFrameBuffer.h>
#include <ImfInputFile.h>
#include <ImfOutputFile.h>
#include <ImfHeader.h>
#include <ImfIntAttribute.h>
#include <ImfMatrixAttribute.h>
#include <ImfRgbaFile.h>
#include <ImfStringAttribute.h>
#include <ImfVecAttribute.h>

#include <Iex.h>
#include <ImfIO.h>

#include <algorithm>
#include <cstring>
#include <exception>

#include <span>

namespace firmament {

namespace {

// OpenEXR reads from and writes to memory: a file is read whole first, and written whole through
// writeFileBytes (core/FileIO.h), which checks every byte reached the disk. OpenEXR's own file
// stream writes its last buffer when it is destroyed, where a full disk goes unreported.
class MemoryInput : public Imf::IStream {
public:
    MemoryInput(std::span<const std::uint8_t> bytes, const std::string& name) : Imf::IStream(name.c_str()), bytes_(bytes) {}
    bool read(char c[], int n) override {
        if (n < 0 || static_cast<std::uint64_t>(n) > bytes_.size() - position_) throw Iex::InputExc("unexpected end of file");
        std::memcpy(c, bytes_.data() + position_, static_cast<size_t>(n));
        position_ += static_cast<std::uint64_t>(n);
        return position_ < bytes_.size();
    }
    std::uint64_t tellg() override { return position_; }
    void seekg(std::uint64_t position) override { position_ = std::min<std::uint64_t>(position, bytes_.size()); }

private:
    std::span<const std::uint8_t> bytes_;
    std::uint64_t position_ = 0;
};

class MemoryOutput : public Imf::OStream {
public:
    explicit MemoryOutput(const std::string& name) : Imf::OStream(name.c_str()) {}
    void write(const char c[], int n) override {
        const size_t end = static_cast<size_t>(position_) + static_cast<size_t>(n);
        if (bytes.size() < end) bytes.resize(end);
        std::memcpy(bytes.data() + position_, c, static_cast<size_t>(n));
        position_ = end;
    }
    std::uint64_t tellp() override { return position_; }
    void seekp(std::uint64_t position) override { position_ = position; }
    std::vector<std::uint8_t> bytes;

private:
    std::uint64_t position_ = 0;
};

// A decoded image's size from its data window, refused when it is empty, inverted or larger than
// the readers' limit (core/ImageLimits.h), or when `valueBytes` per pixel would be more than the
// file could hold: deflate expands at most 1032 times, and a half channel read as four floats
// grows 8 times more, so a file decodes to at most 8,256 times its size (a damaged 400-byte
// header once asked for 28 GiB).
void sizeOfDataWindow(const Imath::Box2i& window, size_t fileBytes, size_t valueBytes, int& width, int& height) {
    const std::int64_t w = static_cast<std::int64_t>(window.max.x) - window.min.x + 1;
    const std::int64_t h = static_cast<std::int64_t>(window.max.y) - window.min.y + 1;
    if (const std::string why = checkImageSize(w, h); !why.empty()) throw Error("its data window: " + why);
    constexpr double kMaxExpansion = 1032.0 * 8.0;
    if (static_cast<double>(w) * static_cast<double>(h) * static_cast<double>(valueBytes) >
        kMaxExpansion * static_cast<double>(fileBytes) + 1024.0 * 1024.0)
        throw Error("its data window (" + std::to_string(w) + " x " + std::to_string(h) + ") is too large for a file of " +
                    std::to_string(fileBytes) + " bytes");
    width = static_cast<int>(w);
    height = static_cast<int>(h);
}

Imath::M44f toImath(const glm::mat4& m) {
    Imath::M44f out;
    for (int i = 0; i < 4; ++i)
        for (int j = 0; j < 4; ++j) out[i][j] = m[i][j];
    return out;
}

glm::mat4 fromImath(const Imath::M44f& m) {
    glm::mat4 out;
    for (int i = 0; i < 4; ++i)
        for (int j = 0; j < 4; ++j) out[i][j] = m[i][j];
    return out;
}

void insertAttribute(Imf::Header& header, const std::string& name, const ExrAttribute& value) {
    std::visit(
        [&](const auto& v) {
            using T = std::decay_t<decltype(v)>;
            if constexpr (std::is_same_v<T, std::string>) header.insert(name, Imf::StringAttribute(v));
            else if constexpr (std::is_same_v<T, float>) header.insert(name, Imf::FloatAttribute(v));
            else if constexpr (std::is_same_v<T, int>) header.insert(name, Imf::IntAttribute(v));
            else if constexpr (std::is_same_v<T, glm::vec3>) header.insert(name, Imf::V3fAttribute(Imath::V3f(v.x, v.y, v.z)));
            else if constexpr (std::is_same_v<T, glm::ivec2>) header.insert(name, Imf::V2iAttribute(Imath::V2i(v.x, v.y)));
            else header.insert(name, Imf::M44fAttribute(toImath(v)));
        },
        value);
}

ExrAttributes readAttributes(const Imf::Header& header) {
    ExrAttributes out;
    for (auto it = header.begin(); it != header.end(); ++it) {
        const Imf::Attribute& a = it.attribute();
        if (auto* s = dynamic_cast<const Imf::StringAttribute*>(&a)) out[it.name()] = s->value();
        else if (auto* f = dynamic_cast<const Imf::FloatAttribute*>(&a)) out[it.name()] = f->value();
        else if (auto* n = dynamic_cast<const Imf::IntAttribute*>(&a)) out[it.name()] = n->value();
        else if (auto* v3 = dynamic_cast<const Imf::V3fAttribute*>(&a))
            out[it.name()] = glm::vec3(v3->value().x, v3->value().y, v3->value().z);
        else if (auto* v2 = dynamic_cast<const Imf::V2iAttribute*>(&a))
            out[it.name()] = glm::ivec2(v2->value().x, v2->value().y);
        else if (auto* m = dynamic_cast<const Imf::M44fAttribute*>(&a)) out[it.name()] = fromImath(m->value());
    }
    return out;
}

}  // namespace

void writeExr(const std::filesystem::path& path, const HalfRgbaImage& image, const ExrAttributes& attributes) {
    if (image.width <= 0 || image.height <= 0 ||
        image.halfBits.size() != static_cast<size_t>(image.width) * image.height * 4)
        throw Error("writeExr: image size does not match its pixel data");
    std::vector<std::uint8_t> bytes;
    try {
        Imf::Header header(image.width, image.height);
        header.compression() = Imf::ZIP_COMPRESSION;
        for (const auto& [name, value] : attributes) insertAttribute(header, name, value);

        std::vector<Imf::Rgba> pixels(static_cast<size_t>(image.width) * image.height);
        for (size_t i = 0; i < pixels.size(); ++i) {
            pixels[i].r.setBits(image.halfBits[i * 4 + 0]);
            pixels[i].g.setBits(image.halfBits[i * 4 + 1]);
            pixels[i].b.setBits(image.halfBits[i * 4 + 2]);
            pixels[i].a.setBits(image.halfBits[i * 4 + 3]);
        }
        MemoryOutput encoded(path.string());
        {
            Imf::RgbaOutputFile file(encoded, header, Imf::WRITE_RGBA);
            file.setFrameBuffer(pixels.data(), 1, static_cast<size_t>(image.width));
            file.writePixels(image.height);
        }
        bytes = std::move(encoded.bytes);
    } catch (const std::exception& e) {
        throw Error("cannot write the EXR file '" + path.string() + "': " + e.what());
    }
    writeFileBytes(path, bytes);
}

namespace {

// 32-bit float pixels of `channels.size()` interleaved channels, written under those names.
void writeFloatChannels(const std::filesystem::path& path, int width, int height, const std::vector<float>& values,
                        std::span<const char* const> channels, const ExrAttributes& attributes) {
    const size_t count = channels.size();
    if (width <= 0 || height <= 0 || values.size() != static_cast<size_t>(width) * static_cast<size_t>(height) * count)
        throw Error("writeExr: image size does not match its pixel data");
    std::vector<std::uint8_t> bytes;
    try {
        Imf::Header header(width, height);
        header.compression() = Imf::ZIP_COMPRESSION;
        for (const auto& [name, value] : attributes) insertAttribute(header, name, value);
        Imf::FrameBuffer frame;
        for (size_t c = 0; c < count; ++c) {
            header.channels().insert(channels[c], Imf::Channel(Imf::FLOAT));
            frame.insert(channels[c], Imf::Slice(Imf::FLOAT, const_cast<char*>(reinterpret_cast<const char*>(values.data() + c)),
                                                 sizeof(float) * count, sizeof(float) * count * static_cast<size_t>(width)));
        }
        MemoryOutput encoded(path.string());
        {
            Imf::OutputFile file(encoded, header);
            file.setFrameBuffer(frame);
            file.writePixels(height);
        }
        bytes = std::move(encoded.bytes);
    } catch (const std::exception& e) {
        throw Error("cannot write the EXR file '" + path.string() + "': " + e.what());
    }
    writeFileBytes(path, bytes);
}

// The named channels as interleaved 32-bit floats (any pixel type, converted; a channel the file
// lacks reads as zero unless `required`).
void readFloatChannels(std::span<const std::uint8_t> bytes, const std::string& name, std::span<const char* const> channels, bool required,
                       int& width, int& height, std::vector<float>& values, ExrAttributes& attributes) {
    try {
        MemoryInput input(bytes, name);
        Imf::InputFile file(input);
        for (const char* channel : channels)
            if (required && !file.header().channels().findChannel(channel)) throw Error(std::string("it has no channel ") + channel);
        const Imath::Box2i window = file.header().dataWindow();
        const size_t count = channels.size();
        sizeOfDataWindow(window, bytes.size(), sizeof(float) * channels.size(), width, height);
        values.assign(static_cast<size_t>(width) * static_cast<size_t>(height) * count, 0.0f);
        char* base = reinterpret_cast<char*>(values.data()) -
                     (static_cast<std::ptrdiff_t>(window.min.x) + static_cast<std::ptrdiff_t>(window.min.y) * width) *
                         static_cast<std::ptrdiff_t>(sizeof(float) * count);
        Imf::FrameBuffer frame;
        for (size_t c = 0; c < count; ++c)
            frame.insert(channels[c], Imf::Slice(Imf::FLOAT, base + c * sizeof(float), sizeof(float) * count,
                                                 sizeof(float) * count * static_cast<size_t>(width)));
        file.setFrameBuffer(frame);
        file.readPixels(window.min.y, window.max.y);
        attributes = readAttributes(file.header());
    } catch (const std::exception& e) {
        throw Error("cannot read the EXR file '" + name + "': " + e.what());
    }
}

constexpr const char* kRgba[4] = {"R", "G", "B", "A"};
constexpr const char* kLuminance[1] = {"Y"};

}  // namespace

void writeExr(const std::filesystem::path& path, const FloatRgbaImage& image, const ExrAttributes& attributes) {
    writeFloatChannels(path, image.width, image.height, image.rgba, kRgba, attributes);
}

FloatExrFile decodeFloatExr(std::span<const std::uint8_t> bytes, const std::string& name) {
    FloatExrFile out;
    readFloatChannels(bytes, name, kRgba, false, out.image.width, out.image.height, out.image.rgba, out.attributes);
    return out;
}

FloatExrFile readFloatExr(const std::filesystem::path& path) { return decodeFloatExr(readFileBytes(path), path.string()); }

void writeExr(const std::filesystem::path& path, const FloatImage& image, const ExrAttributes& attributes) {
    writeFloatChannels(path, image.width, image.height, image.values, kLuminance, attributes);
}

FloatImageFile decodeFloatChannelExr(std::span<const std::uint8_t> bytes, const std::string& name) {
    FloatImageFile out;
    readFloatChannels(bytes, name, kLuminance, true, out.image.width, out.image.height, out.image.values, out.attributes);
    return out;
}

FloatImageFile readFloatChannelExr(const std::filesystem::path& path) { return decodeFloatChannelExr(readFileBytes(path), path.string()); }

ExrFile readExr(const std::filesystem::path& path) { return decodeExr(readFileBytes(path), path.string()); }

ExrFile decodeExr(std::span<const std::uint8_t> bytes, const std::string& name) {
    try {
        MemoryInput input(bytes, name);
        Imf::RgbaInputFile file(input);
        const Imath::Box2i window = file.dataWindow();
        ExrFile out;
        sizeOfDataWindow(window, bytes.size(), sizeof(Imf::Rgba), out.image.width, out.image.height);
        std::vector<Imf::Rgba> pixels(static_cast<size_t>(out.image.width) * out.image.height);
        // OpenEXR addresses pixel (x, y) at base + x + y * width: the base is offset by the data
        // window's origin, in 64 bits (a far origin once overflowed int, found by fuzzing).
        const std::ptrdiff_t origin = static_cast<std::ptrdiff_t>(window.min.x) + static_cast<std::ptrdiff_t>(window.min.y) * out.image.width;
        file.setFrameBuffer(pixels.data() - origin, 1, static_cast<size_t>(out.image.width));
        file.readPixels(window.min.y, window.max.y);
        out.image.halfBits.resize(pixels.size() * 4);
        for (size_t i = 0; i < pixels.size(); ++i) {
            out.image.halfBits[i * 4 + 0] = pixels[i].r.bits();
            out.image.halfBits[i * 4 + 1] = pixels[i].g.bits();
            out.image.halfBits[i * 4 + 2] = pixels[i].b.bits();
            out.image.halfBits[i * 4 + 3] = pixels[i].a.bits();
        }
        out.attributes = readAttributes(file.header());
        return out;
    } catch (const std::exception& e) {
        throw Error("cannot read the EXR file '" + name + "': " + e.what());
    }
}

}  // namespace firmament
