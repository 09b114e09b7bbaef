#include "atmosphere/hillaire/HillaireTableFiles.h"

#include "core/Error.h"
#include "tables/TableFiles.h"

#include <array>

namespace firmament {

namespace {

struct TableFile {
    const char* file;
    const char* name;
    const char* layout;
    Texture2D HillaireTables::*texture;
};

const std::array<TableFile, 3> kFiles{{
    {"hillaire-transmittance.exr", "transmittance T(r, mu) to the top of the atmosphere",
     "x: u_mu (the zenith in the first column, the horizon in the last), y: u_r (the ground in the top row)", &HillaireTables::transmittance},
    {"hillaire-multiple-scattering.exr",
     "multiple scattering Psi_ms(r, mu_s) per unit sun irradiance: the second order's isotropic light at the point over 1 - f_ms",
     "x: 0.5 + 0.5 mu_s, y: (r - Rg) / (Rt - Rg) (the ground in the top row)", &HillaireTables::multipleScattering},
    {"hillaire-irradiance.exr", "sky irradiance E(r, mu_s) on a horizontal surface per unit sun irradiance, from the model's own radiance",
     "x: 0.5 + 0.5 mu_s, y: (r - Rg) / (Rt - Rg) (the ground in the top row)", &HillaireTables::irradiance},
}};

ExrAttributes commonAttributes(const HillaireParameters& p, const std::string& key) {
    ExrAttributes a = p.physics.exrAttributes();
    a["firmament.lut.key"] = key;
    a["firmament.lut.model"] = std::string("Hillaire 2020");
    a["firmament.lut.sampling"] = describeTables(p);
    a["firmament.lut.parameterization"] = std::string(
        "transmittance: H = sqrt(Rt^2 - Rg^2), rho = sqrt(r^2 - Rg^2), u_r = rho / H, u_mu = (d - (Rt - r)) / (rho + H - (Rt - r)) with d the "
        "distance to the top along mu (no ray meets the ground). Multiple scattering and irradiance: linear in mu_s and in r. Texel centres "
        "sit at u = i / (N - 1).");
    return a;
}

}  // namespace

void writeTables(ID3D11Device* device, ID3D11DeviceContext* context, const HillairePrecomputation& tables, const std::string& key,
                 const std::filesystem::path& folder, const std::string& prefix) {
    std::error_code ec;
    std::filesystem::create_directories(folder, ec);
    if (ec) throw Error("cannot create the folder '" + folder.string() + "': " + ec.message());
    for (const TableFile& f : kFiles) {
        const Texture2D& texture = tables.tables().*f.texture;
        ExrAttributes a = commonAttributes(tables.parameters(), key);
        a["firmament.lut.name"] = std::string(f.name);
        a["firmament.lut.dimensions"] = std::to_string(texture.width) + " x " + std::to_string(texture.height);
        a["firmament.lut.layout"] = std::string(f.layout);
        writeExr(folder / (prefix + f.file), floatRgbaImage(readTexture2D(device, context, texture.texture.Get())), a);
    }
}

std::string readTables(ID3D11DeviceContext* context, HillairePrecomputation& tables, const std::string& key, const std::filesystem::path& folder,
                       const std::string& prefix) {
    std::error_code ec;
    if (!std::filesystem::exists(folder / (prefix + kFiles.back().file), ec)) return "missing";
    std::array<FloatExrFile, kFiles.size()> files;
    for (size_t i = 0; i < kFiles.size(); ++i) {  // read and check everything before changing any texture
        const auto path = folder / (prefix + kFiles[i].file);
        try {
            files[i] = readFloatExr(path);
        } catch (const Error& e) {
            return e.what();
        }
        const Texture2D& texture = tables.tables().*kFiles[i].texture;
        if (auto why = checkTableHeader(files[i].attributes, key, texture.width, texture.height, files[i].image.width, files[i].image.height);
            !why.empty())
            return path.string() + ": " + why;
    }
    for (size_t i = 0; i < kFiles.size(); ++i) {
        const Texture2D& texture = tables.tables().*kFiles[i].texture;
        context->UpdateSubresource(texture.texture.Get(), 0, nullptr, files[i].image.rgba.data(), static_cast<UINT>(texture.width * 16), 0);
    }
    tables.markComplete();
    return {};
}

}  // namespace firmament
