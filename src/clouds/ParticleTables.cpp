#include "clouds/ParticleTables.h"

#include "core/Error.h"
#include "gpu/Readback.h"
#include "tables/TableFiles.h"

#include <cstring>

namespace firmament {

namespace {
const ShaderKey kOpticalDepth{"clouds/precompute_optical_depth.hlsl", "main", "cs_5_0", {}};
constexpr unsigned kGroup[2] = {8, 8};
// Slices per unit of work: about a quarter of a second on the WARP device at the default size.
constexpr unsigned kSlicesPerUnit = 64;
constexpr int kFormatVersion = 1;  // raise when the files' layout changes

void runUnit(ID3D11DeviceContext* context, ShaderLibrary& shaders, const WorkUnit<ParticleTableStage>& unit, const ParticleTableParameters& p,
             const ParticleTables& tables, ParticleTableScratch& scratch) {
    const OpticalDepthTableSize& n = p.opticalDepth;
    gpu::ParticleTableConstants c{};
    c.sizes = glm::uvec4(n.entryZenith, n.entryAzimuth, n.directionZenith, n.directionAzimuth);
    c.options = glm::uvec4(static_cast<unsigned>(p.method), static_cast<unsigned>(n.steps), unit.first, 0u);
    scratch.constants.update(context, c);
    context->CSSetConstantBuffers(0, 1, scratch.constants.address());
    bindCompute(context, shaders.computeShader(kOpticalDepth), {}, {tables.opticalDepth.uav.Get()});
    context->Dispatch(groupCount(static_cast<unsigned>(n.width()), kGroup[0]), groupCount(static_cast<unsigned>(n.height()), kGroup[1]), unit.end - unit.first);
    unbindCompute(context, 0, 1);
}

const char* methodName(ParticleDensityMethod method) { return kParticleDensityMethodNames[static_cast<size_t>(method)].data(); }
}  // namespace

std::string ParticleTableParameters::describe() const {
    return std::string("particle density: ") + methodName(method) + "; optical depth " + opticalDepth.describe() +
           "; format=" + std::to_string(kFormatVersion);
}

std::string stageName(ParticleTableStage stage, int) {
    switch (stage) {
        case ParticleTableStage::OpticalDepth: return "optical depth";
    }
    return {};
}

std::string describeTables(const ParticleTableParameters& parameters) {
    return "the particle's optical depth " + parameters.opticalDepth.describe() + ", " + methodName(parameters.method);
}

std::span<const ShaderKey> particleTableShaders() {
    static const ShaderKey all[] = {kOpticalDepth};
    return all;
}

ParticleTableScratch::ParticleTableScratch(ID3D11Device* device, const ParticleTableParameters&, const ParticleTables&) : constants(device) {}

ParticleTablePrecomputation::ParticleTablePrecomputation(ID3D11Device* device, const ParticleTableParameters& parameters)
    : StagedComputation("clouds: ", device, parameters, runUnit) {
    const OpticalDepthTableSize& n = parameters_.opticalDepth;
    tables_.opticalDepth = createTexture3D(device, n.width(), n.height(), n.depth(), DXGI_FORMAT_R32_FLOAT,
                                           D3D11_BIND_SHADER_RESOURCE | D3D11_BIND_UNORDERED_ACCESS);
    addSlabs(ParticleTableStage::OpticalDepth, static_cast<unsigned>(n.depth()), kSlicesPerUnit);
}

std::string particleTableKey(const ParticleTableParameters& parameters, ShaderLibrary& shaders) {
    return tableKey(parameters.describe(), shaders, particleTableShaders());
}

// The 3D table as a 2D image of tiles (entry azimuth x entry zenith): tile column the direction
// zenith, tile row the direction azimuth; and back.
namespace {
const char* kOpticalDepthFile = "cloud-optical-depth.exr";

ExrAttributes attributes(const ParticleTableParameters& p, const std::string& key) {
    const OpticalDepthTableSize& n = p.opticalDepth;
    ExrAttributes a;
    a["firmament.lut.key"] = key;
    a["firmament.lut.formatVersion"] = kFormatVersion;
    a["firmament.lut.name"] = std::string("cloud particle: mean density along a chord of the unit sphere (Yusov 2014)");
    a["firmament.lut.dimensions"] = n.describe();
    a["firmament.lut.density"] = std::string(methodName(p.method));
    a["firmament.lut.parameterization"] = std::string(
        "entry point s on the unit sphere (y up): zenith theta_s / pi, azimuth atan2(s.z, s.x) / 2pi + 1/2; direction d: angle "
        "from -s over pi/2, azimuth in the frame Z = -s, X = normalize(Z x y), Y = Z x X, over 2pi, + 1/2. Texel centres.");
    a["firmament.lut.layout"] = std::string("tiles of ") + std::to_string(n.entryAzimuth) + " x " + std::to_string(n.entryZenith) +
                                " texels (x entry azimuth, y entry zenith); tile column: direction zenith (" + std::to_string(n.directionZenith) +
                                "), tile row: direction azimuth (" + std::to_string(n.directionAzimuth) + ")";
    return a;
}
}  // namespace

void writeTables(ID3D11Device* device, ID3D11DeviceContext* context, const ParticleTablePrecomputation& tables, const std::string& key,
                 const std::filesystem::path& folder, const std::string& prefix) {
    const OpticalDepthTableSize& n = tables.parameters().opticalDepth;
    std::error_code ec;
    std::filesystem::create_directories(folder, ec);
    if (ec) throw Error("cannot create the folder '" + folder.string() + "': " + ec.message());
    const ReadbackVolume volume = readTexture3D(device, context, tables.tables().opticalDepth.texture.Get());
    FloatImage image{n.width() * n.directionZenith, n.height() * n.directionAzimuth, {}};
    image.values.resize(static_cast<size_t>(image.width) * image.height);
    for (int z = 0; z < n.depth(); ++z) {
        const int column = z % n.directionZenith, row = z / n.directionZenith;
        for (int y = 0; y < n.height(); ++y)
            std::memcpy(image.values.data() + (static_cast<size_t>(row) * n.height() + y) * image.width + static_cast<size_t>(column) * n.width(),
                        volume.bytes.data() + (static_cast<size_t>(z) * n.height() + y) * n.width() * 4, static_cast<size_t>(n.width()) * 4);
    }
    writeExr(folder / (prefix + kOpticalDepthFile), image, attributes(tables.parameters(), key));
}

std::string readTables(ID3D11DeviceContext* context, ParticleTablePrecomputation& tables, const std::string& key, const std::filesystem::path& folder,
                       const std::string& prefix) {
    const OpticalDepthTableSize& n = tables.parameters().opticalDepth;
    const auto path = folder / (prefix + kOpticalDepthFile);
    std::error_code ec;
    if (!std::filesystem::exists(path, ec)) return "missing";
    FloatImageFile file;
    try {
        file = readFloatChannelExr(path);
    } catch (const Error& e) {
        return e.what();
    }
    if (auto why = checkTableHeader(file.attributes, key, n.width() * n.directionZenith, n.height() * n.directionAzimuth, file.image.width,
                                    file.image.height);
        !why.empty())
        return path.string() + ": " + why;
    std::vector<float> volume(static_cast<size_t>(n.width()) * n.height() * n.depth());
    for (int z = 0; z < n.depth(); ++z) {
        const int column = z % n.directionZenith, row = z / n.directionZenith;
        for (int y = 0; y < n.height(); ++y)
            std::memcpy(volume.data() + (static_cast<size_t>(z) * n.height() + y) * n.width(),
                        file.image.values.data() + (static_cast<size_t>(row) * n.height() + y) * file.image.width + static_cast<size_t>(column) * n.width(),
                        static_cast<size_t>(n.width()) * 4);
    }
    context->UpdateSubresource(tables.tables().opticalDepth.texture.Get(), 0, nullptr, volume.data(), static_cast<UINT>(n.width() * 4),
                               static_cast<UINT>(n.width() * n.height() * 4));
    tables.markComplete();
    return {};
}

}  // namespace firmament
