#include "core/ExrImage.h"

#include "core/Error.h"

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

#include <exception>

#include <span>

namespace firmament {

namespace {

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
        Imf::RgbaOutputFile file(path.string().c_str(), header, Imf::WRITE_RGBA);
        file.setFrameBuffer(pixels.data(), 1, static_cast<size_t>(image.width));
        file.writePixels(image.height);
    } catch (const std::exception& e) {
        throw Error("cannot write the EXR file '" + path.string() + "': " + e.what());
    }
}

namespace {

// 32-bit float pixels of `channels.size()` interleaved channels, written under those names.
void writeFloatChannels(const std::filesystem::path& path, int width, int height, const std::vector<float>& values,
                        std::span<const char* const> channels, const ExrAttributes& attributes) {
    const size_t count = channels.size();
    if (width <= 0 || height <= 0 || values.size() != static_cast<size_t>(width) * static_cast<size_t>(height) * count)
        throw Error("writeExr: image size does not match its pixel data");
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
        Imf::OutputFile file(path.string().c_str(), header);
        file.setFrameBuffer(frame);
        file.writePixels(height);
    } catch (const std::exception& e) {
        throw Error("cannot write the EXR file '" + path.string() + "': " + e.what());
    }
}

// The named channels as interleaved 32-bit floats (any pixel type, converted; a channel the file
// lacks reads as zero unless `required`).
void readFloatChannels(const std::filesystem::path& path, std::span<const char* const> channels, bool required, int& width, int& height,
                       std::vector<float>& values, ExrAttributes& attributes) {
    try {
        Imf::InputFile file(path.string().c_str());
        for (const char* name : channels)
            if (required && !file.header().channels().findChannel(name)) throw Error(std::string("it has no channel ") + name);
        const Imath::Box2i window = file.header().dataWindow();
        const size_t count = channels.size();
        width = window.max.x - window.min.x + 1;
        height = window.max.y - window.min.y + 1;
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
        throw Error("cannot read the EXR file '" + path.string() + "': " + e.what());
    }
}

constexpr const char* kRgba[4] = {"R", "G", "B", "A"};
constexpr const char* kLuminance[1] = {"Y"};

}  // namespace

void writeExr(const std::filesystem::path& path, const FloatRgbaImage& image, const ExrAttributes& attributes) {
    writeFloatChannels(path, image.width, image.height, image.rgba, kRgba, attributes);
}

FloatExrFile readFloatExr(const std::filesystem::path& path) {
    FloatExrFile out;
    readFloatChannels(path, kRgba, false, out.image.width, out.image.height, out.image.rgba, out.attributes);
    return out;
}

void writeExr(const std::filesystem::path& path, const FloatImage& image, const ExrAttributes& attributes) {
    writeFloatChannels(path, image.width, image.height, image.values, kLuminance, attributes);
}

FloatImageFile readFloatChannelExr(const std::filesystem::path& path) {
    FloatImageFile out;
    readFloatChannels(path, kLuminance, true, out.image.width, out.image.height, out.image.values, out.attributes);
    return out;
}

ExrFile readExr(const std::filesystem::path& path) {
    try {
        Imf::RgbaInputFile file(path.string().c_str());
        const Imath::Box2i window = file.dataWindow();
        ExrFile out;
        out.image.width = window.max.x - window.min.x + 1;
        out.image.height = window.max.y - window.min.y + 1;
        std::vector<Imf::Rgba> pixels(static_cast<size_t>(out.image.width) * out.image.height);
        file.setFrameBuffer(pixels.data() - window.min.x - window.min.y * out.image.width, 1,
                            static_cast<size_t>(out.image.width));
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
        throw Error("cannot read the EXR file '" + path.string() + "': " + e.what());
    }
}

}  // namespace firmament
