#include "atmosphere/bruneton/BrunetonTableFiles.h"

#include "tables/TableFiles.h"
#include "core/Error.h"
#include "gpu/Readback.h"

#include <cstring>

namespace firmament {

namespace {

constexpr const char* kTransmittanceFile = "bruneton-transmittance.exr";
constexpr const char* kIrradianceFile = "bruneton-irradiance.exr";
constexpr const char* kInscatterFile = "bruneton-inscatter.exr";

ExrAttributes commonAttributes(const BrunetonParameters& p, const std::string& key) {
    ExrAttributes a = p.physics.exrAttributes();
    a["firmament.lut.key"] = key;
    a["firmament.lut.model"] = std::string("Bruneton and Neyret 2008");
    a["firmament.atmosphere.groundAlbedo"] = static_cast<float>(p.groundAlbedo);
    a["firmament.lut.parameterization"] = std::string(
        "in-scatter: u_r = rho / H (rho = sqrt(r^2 - Rg^2), H = sqrt(Rt^2 - Rg^2)); u_mu: rays to the ground in the lower half, "
        "distance to the ground / rho (the horizon at the first row), the others in the upper half, distance to the top / (rho + H) "
        "(the zenith first); u_mu_s = max((1 - exp(-3 mu_s - 0.6)) / (1 - exp(-3.6)), 0); u_nu = (1 + nu) / 2. Transmittance: "
        "u_r = sqrt((r - Rg) / (Rt - Rg)), u_mu = atan((mu + 0.15) / 1.15 tan 1.5) / 1.5. Irradiance: linear in r and in mu_s "
        "from -0.2 to 1. Texel centres sit at u = i / (N - 1).");
    return a;
}

}  // namespace

void writeTables(ID3D11Device* device, ID3D11DeviceContext* context, const BrunetonPrecomputation& tables,
                           const std::string& key, const std::filesystem::path& folder, const std::string& prefix) {
    const BrunetonParameters& p = tables.parameters();
    const auto& n = p.lut;
    std::error_code ec;
    std::filesystem::create_directories(folder, ec);
    if (ec) throw Error("cannot create the folder '" + folder.string() + "': " + ec.message());

    ExrAttributes a = commonAttributes(p, key);
    a["firmament.lut.name"] = std::string("transmittance T(r, mu) to the top of the atmosphere");
    a["firmament.lut.dimensions"] = std::to_string(n.transmittanceMu) + " x " + std::to_string(n.transmittanceR) + " (mu, r)";
    a["firmament.lut.layout"] = std::string("x: u_mu, y: u_r (the ground in the top row). Rays that meet the ground hold the grazing ray's value.");
    writeExr(folder / (prefix + kTransmittanceFile), floatRgbaImage(readTexture2D(device, context, tables.tables().transmittance.texture.Get())), a);

    a = commonAttributes(p, key);
    a["firmament.lut.name"] = std::string("sky irradiance E(r, mu_s) on a horizontal surface, orders 1 to N - 1, per unit sun irradiance");
    a["firmament.lut.dimensions"] = std::to_string(n.irradianceMuS) + " x " + std::to_string(n.irradianceR) + " (mu_s, r)";
    a["firmament.lut.layout"] = std::string("x: u_mu_s, y: u_r (the ground in the top row)");
    writeExr(folder / (prefix + kIrradianceFile), floatRgbaImage(readTexture2D(device, context, tables.tables().irradiance.texture.Get())), a);

    const ReadbackVolume volume = readTexture3D(device, context, tables.tables().inscatter.texture.Get());
    HalfRgbaImage inscatter{volume.width, volume.height * volume.depth, std::vector<std::uint16_t>(volume.bytes.size() / 2)};
    std::memcpy(inscatter.halfBits.data(), volume.bytes.data(), volume.bytes.size());  // layers follow each other: already stacked
    a = commonAttributes(p, key);
    a["firmament.lut.name"] = std::string(
        "in-scatter S(r, mu, mu_s, nu) per unit sun irradiance: RGB Rayleigh single scattering plus every higher order divided by "
        "P_R(nu) (1/sr), A single Mie scattering's red channel without its phase function");
    a["firmament.lut.scale"] = std::string("the texels hold the light times " + std::to_string(kBrunetonInscatterScale));
    a["firmament.lut.dimensions"] = std::to_string(n.r) + " x " + std::to_string(n.mu) + " x " + std::to_string(n.muS) + " x " +
                                    std::to_string(n.nu) + " (r, mu, mu_s, nu)";
    a["firmament.lut.layout"] = "x: nu slice * " + std::to_string(n.muS) + " + mu_s; y: radius layer * " + std::to_string(n.mu) +
                                " + mu (each layer's rows 0 to N_mu/2 - 1 meet the ground)";
    writeExr(folder / (prefix + kInscatterFile), inscatter, a);
}

std::string readTables(ID3D11DeviceContext* context, BrunetonPrecomputation& tables, const std::string& key,
                                 const std::filesystem::path& folder, const std::string& prefix) {
    const auto& n = tables.parameters().lut;
    const auto transmittancePath = folder / (prefix + kTransmittanceFile), irradiancePath = folder / (prefix + kIrradianceFile),
               inscatterPath = folder / (prefix + kInscatterFile);
    std::error_code ec;
    if (!std::filesystem::exists(inscatterPath, ec)) return "missing";
    FloatExrFile transmittance, irradiance;
    ExrFile inscatter;
    try {  // read and check everything before changing any texture
        transmittance = readFloatExr(transmittancePath);
        irradiance = readFloatExr(irradiancePath);
        inscatter = readExr(inscatterPath);
    } catch (const Error& e) {
        return e.what();
    }
    const glm::ivec3 packed = n.packed3d();
    if (auto why = checkTableHeader(transmittance.attributes, key, n.transmittanceMu, n.transmittanceR, transmittance.image.width,
                                    transmittance.image.height);
        !why.empty())
        return transmittancePath.string() + ": " + why;
    if (auto why = checkTableHeader(irradiance.attributes, key, n.irradianceMuS, n.irradianceR, irradiance.image.width, irradiance.image.height);
        !why.empty())
        return irradiancePath.string() + ": " + why;
    if (auto why = checkTableHeader(inscatter.attributes, key, packed.x, packed.y * packed.z, inscatter.image.width, inscatter.image.height);
        !why.empty())
        return inscatterPath.string() + ": " + why;
    const BrunetonTables& t = tables.tables();
    context->UpdateSubresource(t.transmittance.texture.Get(), 0, nullptr, transmittance.image.rgba.data(), static_cast<UINT>(n.transmittanceMu * 16), 0);
    context->UpdateSubresource(t.irradiance.texture.Get(), 0, nullptr, irradiance.image.rgba.data(), static_cast<UINT>(n.irradianceMuS * 16), 0);
    context->UpdateSubresource(t.inscatter.texture.Get(), 0, nullptr, inscatter.image.halfBits.data(), static_cast<UINT>(packed.x * 8),
                               static_cast<UINT>(packed.x * packed.y * 8));
    tables.markComplete();
    return {};
}

}  // namespace firmament
