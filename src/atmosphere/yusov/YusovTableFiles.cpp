#include "atmosphere/yusov/YusovTableFiles.h"

#include "tables/TableFiles.h"
#include "core/Error.h"
#include "gpu/Readback.h"

#include <cstdio>
#include <cstring>

namespace firmament {

namespace {

constexpr int kFormatVersion = 4;  // raise when the files' layout changes

std::string dimensions(const LutDimensions& n) {
    char text[128];
    std::snprintf(text, sizeof(text), "%d x %d x %d x %d (altitude, view zenith, sun zenith, sun-view)", n.height, n.viewZenith,
                  n.sunZenith, n.sunView);
    return text;
}

ExrAttributes commonAttributes(const AtmosphereParameters& p, const std::string& key) {
    ExrAttributes a = p.exrAttributes();
    a["firmament.lut.key"] = key;
    a["firmament.lut.formatVersion"] = kFormatVersion;
    a["firmament.lut.parameterization"] = std::string(
        "Yusov 2013, eq. 4-7: u_h = sqrt(h / H_atm); view zenith: 0.5 ((c - c_h) / (1 - c_h))^0.2 + 0.5 above "
        "the horizon, 0.5 ((c_h - c) / (c_h + 1))^0.2 below, c_h = -sqrt(h (2R + h)) / (R + h); sun zenith: 0.5 (atan(max(c, "
        "-0.1975) tan(1.386)) / 1.1 + 0.74); sun-view: 0.5 +- 0.5 |2 (theta / pi - 0.5)|^1.5. Texel centres sit at u = i / (N - 1); "
        "the view zenith's halves each span N / 2 texels.");
    return a;
}

struct FourDimensionalTable {
    const Texture3D* texture;
    const char* file;
    const char* name;
    int banks;  // of altitude texels side by side: 2 for the tables of species (Rayleigh, Mie)
};

std::vector<FourDimensionalTable> fourDimensionalTables(const YusovTables& t) {
    return {{&t.singleScattering, "single-scattering.exr",
             "single scattering L^(1) by species without the phase functions: S_R, then S_M, per unit sun irradiance", 2},
            {&t.highOrderScattering, "high-order-scattering.exr", "high-order scattering L^H = L^(2) + ... + L^(N), per unit sun irradiance (1/sr)", 1},
            {&t.multipleScattering, "multiple-scattering.exr",
             "multiple scattering L^M = L^(1) + L^H by species: S_R + L^H / P_R(cos sun-view), then S_M, per unit sun irradiance", 2}};
}

std::string tiledLayout(const LutDimensions& n, int banks) {
    const std::string x = banks == 2 ? "x altitude, the Rayleigh bank (" + std::to_string(n.height) + ") then the Mie bank" : "x altitude";
    return "tiles of " + std::to_string(banks * n.height) + " x " + std::to_string(n.viewZenith) + " texels: " + x +
           ", y view zenith (rows 0 to N/2-1 below the horizon, from it downwards; rows N/2 to N-1 above it, "
           "from it up to the zenith). Tile column: sun zenith (" + std::to_string(n.sunZenith) + "), tile row: sun-view angle (" +
           std::to_string(n.sunView) + "). The GPU's 3D texture is the tiles stacked as z = row * " + std::to_string(n.sunZenith) +
           " + column.";
}

// The packed 3D table (half RGBA, `banks` * N_h texels wide) as a 2D image of tiles, and back.
HalfRgbaImage tileVolume(const ReadbackVolume& volume, const LutDimensions& n, int banks) {
    const int tileWidth = banks * n.height;
    HalfRgbaImage image{tileWidth * n.sunZenith, n.viewZenith * n.sunView, {}};
    image.halfBits.resize(static_cast<size_t>(image.width) * image.height * 4);
    for (int z = 0; z < volume.depth; ++z) {
        const int column = z % n.sunZenith, row = z / n.sunZenith;
        for (int y = 0; y < volume.height; ++y) {
            const size_t from = (static_cast<size_t>(z) * volume.height + y) * volume.width * 8;
            const size_t to = ((static_cast<size_t>(row) * n.viewZenith + y) * image.width + column * tileWidth) * 4;
            std::memcpy(image.halfBits.data() + to, volume.bytes.data() + from, static_cast<size_t>(volume.width) * 8);
        }
    }
    return image;
}

std::vector<std::uint16_t> untileVolume(const HalfRgbaImage& image, const LutDimensions& n, int banks) {
    const glm::ivec3 packed = n.packed3d();
    const int tileWidth = banks * packed.x;
    std::vector<std::uint16_t> volume(static_cast<size_t>(tileWidth) * packed.y * packed.z * 4);
    for (int z = 0; z < packed.z; ++z) {
        const int column = z % n.sunZenith, row = z / n.sunZenith;
        for (int y = 0; y < packed.y; ++y) {
            const size_t to = (static_cast<size_t>(z) * packed.y + y) * tileWidth * 4;
            const size_t from = ((static_cast<size_t>(row) * n.viewZenith + y) * image.width + column * tileWidth) * 4;
            std::memcpy(volume.data() + to, image.halfBits.data() + from, static_cast<size_t>(tileWidth) * 8);
        }
    }
    return volume;
}

}  // namespace

std::string yusovTableKey(const AtmosphereParameters& parameters, ShaderLibrary& shaders) {
    return tableKey(parameters.describe() + " format=" + std::to_string(kFormatVersion), shaders, yusovPrecomputeShaders());
}

void writeTables(ID3D11Device* device, ID3D11DeviceContext* context, const YusovPrecomputation& tables,
                           const std::string& key, const std::filesystem::path& folder, const std::string& prefix) {
    const AtmosphereParameters& p = tables.parameters();
    const LutDimensions& n = p.lut;
    std::error_code ec;
    std::filesystem::create_directories(folder, ec);
    if (ec) throw Error("cannot create the folder '" + folder.string() + "': " + ec.message());

    // Net density: one texel per pixel.
    const ReadbackImage density = readTexture2D(device, context, tables.tables().netDensity.texture.Get());
    FloatRgbaImage densityImage{density.width, density.height, std::vector<float>(density.bytes.size() / 4)};
    std::memcpy(densityImage.rgba.data(), density.bytes.data(), density.bytes.size());
    ExrAttributes a = commonAttributes(p, key);
    a["firmament.lut.name"] = std::string("net density to the top of the atmosphere");
    a["firmament.lut.dimensions"] = std::to_string(n.netDensityZenith) + " x " + std::to_string(n.netDensityHeight) + " (zenith, altitude)";
    a["firmament.lut.layout"] = std::string(
        "x: cosine of the zenith angle, -1 to 1 at texel centres; y: altitude, u_h = sqrt(h / H_atm), 0 in the top row. "
        "R, G, B: Rayleigh, Mie and ozone density integrated along the ray to the top (m of sea-level density; the ozone "
        "layer's peak density for B). Rays that meet the ground hold the grazing ray's value.");
    writeExr(folder / (prefix + "net-density.exr"), densityImage, a);

    for (const FourDimensionalTable& table : fourDimensionalTables(tables.tables())) {
        a = commonAttributes(p, key);
        a["firmament.lut.name"] = std::string(table.name);
        a["firmament.lut.dimensions"] = dimensions(n);
        a["firmament.lut.layout"] = tiledLayout(n, table.banks);
        a["firmament.lut.scale"] = std::string("the texels hold the light times " + std::to_string(kYusovTableScale));
        writeExr(folder / (prefix + table.file), tileVolume(readTexture3D(device, context, table.texture->texture.Get()), n, table.banks), a);
    }

    const ReadbackImage ambient = readTexture2D(device, context, tables.tables().ambientLight.texture.Get());
    HalfRgbaImage ambientImage{ambient.width, 1, std::vector<std::uint16_t>(ambient.bytes.size() / 2)};
    std::memcpy(ambientImage.halfBits.data(), ambient.bytes.data(), ambient.bytes.size());
    a = commonAttributes(p, key);
    a["firmament.lut.name"] = std::string("ambient sky light: irradiance of the whole sky on a horizontal surface on the ground, per unit sun irradiance");
    a["firmament.lut.dimensions"] = std::to_string(n.ambientLight) + " (sun zenith)";
    a["firmament.lut.layout"] = std::string("x: cosine of the sun's zenith angle, -1 to 1 at texel centres (Yusov 2013, eq. 3)");
    writeExr(folder / (prefix + "ambient-light.exr"), ambientImage, a);
}

std::string readTables(ID3D11DeviceContext* context, YusovPrecomputation& tables, const std::string& key,
                                 const std::filesystem::path& folder, const std::string& prefix) {
    const LutDimensions& n = tables.parameters().lut;
    const auto densityPath = folder / (prefix + "net-density.exr"), ambientPath = folder / (prefix + "ambient-light.exr");
    std::error_code ec;
    if (!std::filesystem::exists(densityPath, ec)) return "missing";
    // Read and check everything before changing any texture.
    FloatExrFile density;
    ExrFile ambient;
    std::vector<ExrFile> fourD;
    const auto tableList = fourDimensionalTables(tables.tables());
    try {
        density = readFloatExr(densityPath);
        for (const FourDimensionalTable& table : tableList) fourD.push_back(readExr(folder / (prefix + table.file)));
        ambient = readExr(ambientPath);
    } catch (const Error& e) {
        return e.what();
    }
    if (auto why = checkTableHeader(density.attributes, key, n.netDensityZenith, n.netDensityHeight, density.image.width, density.image.height);
        !why.empty())
        return densityPath.string() + ": " + why;
    for (size_t i = 0; i < tableList.size(); ++i)
        if (auto why = checkTableHeader(fourD[i].attributes, key, tableList[i].banks * n.height * n.sunZenith, n.viewZenith * n.sunView,
                                        fourD[i].image.width, fourD[i].image.height);
            !why.empty())
            return (folder / (prefix + tableList[i].file)).string() + ": " + why;
    if (auto why = checkTableHeader(ambient.attributes, key, n.ambientLight, 1, ambient.image.width, ambient.image.height); !why.empty())
        return ambientPath.string() + ": " + why;

    context->UpdateSubresource(tables.tables().netDensity.texture.Get(), 0, nullptr, density.image.rgba.data(),
                               static_cast<UINT>(density.image.width * 16), 0);
    const glm::ivec3 packed = n.packed3d();
    for (size_t i = 0; i < tableList.size(); ++i) {
        const int width = tableList[i].banks * packed.x;
        const auto volume = untileVolume(fourD[i].image, n, tableList[i].banks);
        context->UpdateSubresource(tableList[i].texture->texture.Get(), 0, nullptr, volume.data(), static_cast<UINT>(width * 8),
                                   static_cast<UINT>(width * packed.y * 8));
    }
    context->UpdateSubresource(tables.tables().ambientLight.texture.Get(), 0, nullptr, ambient.image.halfBits.data(),
                               static_cast<UINT>(ambient.image.width * 8), 0);
    tables.markComplete();
    return {};
}

}  // namespace firmament
