#include "clouds/DeckDiffusionTable.h"

#include "clouds/SlabDoubling.h"
#include "core/Error.h"
#include "core/ExrImage.h"
#include "tables/TableFileHeaders.h"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <cstdlib>

namespace firmament {

namespace {
constexpr double kPi = 3.14159265358979323846;
// Raise when the file's layout or medium changes (2: the droplets' own phase function, cosines
// even in angle).
constexpr int kFileFormat = 2;
}  // namespace

double DeckDiffusionParameters::thickness(int k) const { return thinnest * std::exp2(static_cast<double>(k) / thicknessesPerOctave); }

double DeckDiffusionParameters::depthShare(int k) const { return 0.5 * (1.0 - std::cos(kPi * k / (depths - 1))); }

double DeckDiffusionParameters::cosine(int k) const { return -std::cos(kPi * k / (cosines - 1)); }

std::string DeckDiffusionParameters::describe() const {
    char text[320];
    std::snprintf(text, sizeof(text),
                  "Henyey-Greenstein g %.6g; %d Gauss nodes a hemisphere; thicknesses %.6g x 2^(k / %d), k < %d; %d depths (cosine spaced); "
                  "%d cosines",
                  asymmetry, gaussPerHemisphere, thinnest, thicknessesPerOctave, thicknesses, depths, cosines);
    return text;
}

double solveDeckMultipleScattering(const DeckDiffusionParameters& p, int gaussPerHemisphere, double depth, double total, double mu) {
    const SlabDoubling slab(p.asymmetry, gaussPerHemisphere, {std::max(std::abs(mu), 1e-3)});
    const SlabDoubling::Field field = slab.diffuse(depth, total), once = slab.singleScattering(depth, total);
    const size_t i = slab.cosines().size() - 1;
    return std::max(mu > 0.0 ? field.down[i] - once.down[i] : field.up[i] - once.up[i], 0.0);
}

DeckDiffusionTable computeDeckDiffusion(const DeckDiffusionParameters& p, const std::function<void(double)>& progress, int onlyThickness) {
    if (p.cosines % 2 != 0 || p.cosines < 2 || p.depths < 2 || p.thicknesses < 2 || p.thicknessesPerOctave < 1)
        throw Error("deck diffusion: the table needs an even count of cosines, two depths and two thicknesses at least");
    // The table's directions ride along as zero-weight directions: the magnitudes of its cosines,
    // each hemisphere's in the same order (|mu_k| = |mu_(M - 1 - k)| = cos(pi j / (M - 1)), j the
    // nearer of k and M - 1 - k).
    std::vector<double> magnitudes;
    for (int j = 0; j < p.cosines / 2; ++j) magnitudes.push_back(std::cos(kPi * j / (p.cosines - 1)));
    const SlabDoubling slab(p.asymmetry, p.gaussPerHemisphere, magnitudes);
    const size_t first = slab.cosines().size() - magnitudes.size();

    DeckDiffusionTable table;
    table.parameters = p;
    table.multiple.assign(static_cast<size_t>(p.cosines) * p.depths * p.thicknesses, 0.0f);
    for (int t = 0; t < p.thicknesses; ++t) {
        if (onlyThickness >= 0 && t != onlyThickness) continue;
        const double total = p.thickness(t);
        // The depths are symmetric about the middle: the layer above depth k is the one below
        // depth (depths - 1 - k).
        std::vector<SlabDoubling::Layer> layers;
        for (int d = 0; d < p.depths; ++d) layers.push_back(slab.layer(d == 0 ? 0.0 : d == p.depths - 1 ? total : total * p.depthShare(d)));
        for (int d = 0; d < p.depths; ++d) {
            const double depth = d == 0 ? 0.0 : d == p.depths - 1 ? total : total * p.depthShare(d);
            const SlabDoubling::Field field = slab.between(layers[static_cast<size_t>(d)], layers[static_cast<size_t>(p.depths - 1 - d)]);
            const SlabDoubling::Field once = slab.singleScattering(depth, total);
            for (int c = 0; c < p.cosines; ++c) {
                const int j = std::min(c, p.cosines - 1 - c);
                const size_t i = first + static_cast<size_t>(j);
                const double multiple = p.cosine(c) > 0.0 ? field.down[i] - once.down[i] : field.up[i] - once.up[i];
                table.multiple[table.index(c, d, t)] = static_cast<float>(std::max(multiple, 0.0));
            }
        }
        if (progress) progress(static_cast<double>(t + 1) / p.thicknesses);
    }
    return table;
}

std::string deckDiffusionKey(const DeckDiffusionParameters& p) {
    return tableKey("deck diffusion: " + p.describe() + "; format=" + std::to_string(kFileFormat));
}

void writeDeckDiffusion(const std::filesystem::path& path, const DeckDiffusionTable& table) {
    const DeckDiffusionParameters& p = table.parameters;
    FloatRgbaImage image{p.cosines, p.depths * p.thicknesses, {}};
    image.rgba.assign(static_cast<size_t>(image.width) * image.height * 4, 0.0f);
    for (size_t k = 0; k < table.multiple.size(); ++k) image.rgba[4 * k] = table.multiple[k];
    ExrAttributes a;
    a["firmament.lut.key"] = deckDiffusionKey(p);
    a["firmament.lut.formatVersion"] = kFileFormat;
    a["firmament.lut.name"] = std::string(
        "deck diffusion: the radiance scattered more than once inside a plane-parallel slab of cloud (albedo 1, Henyey-Greenstein) lit by "
        "the sun along its normal, per unit sun irradiance (1/sr), by doubling and adding in the droplets' own medium (Henyey-Greenstein "
        "g, delta-M truncated only at the solver's order). R: the light; G, B, A: 0");
    a["firmament.lut.dimensions"] = p.describe();
    a["firmament.lut.parameterization"] = std::string(
        "x: the cosine mu = -cos(pi x / (width - 1)) between the light's travel and the sun's (even steps in angle); y within a tile: "
        "the depth's share of the thickness (1 - cos(pi y / (depths - 1))) / 2 from the lit face; tile k: the optical thickness "
        "thinnest x 2^(k / per octave)");
    a["firmament.lut.layout"] = std::string("one tile of cosine x depth per thickness, one above the other, the thinnest at the top");
    a["firmament.lut.generator"] = std::string("firmament --generate-deck-diffusion <file> (tools/generate-cloud-scattering)");
    writeExr(path, image, a);
}

DeckDiffusionTable readDeckDiffusion(const std::filesystem::path& path, const DeckDiffusionParameters& expected) {
    std::error_code ec;
    if (!std::filesystem::exists(path, ec)) throw Error(path.string() + ": deck diffusion's table is missing (tools/generate-cloud-scattering makes it)");
    const FloatExrFile file = readFloatExr(path);
    if (const std::string why = checkTableHeader(file.attributes, deckDiffusionKey(expected), expected.cosines, expected.depths * expected.thicknesses,
                                                 file.image.width, file.image.height);
        !why.empty())
        throw Error(path.string() + ": " + why + "; run tools/generate-cloud-scattering to make it for this program");
    DeckDiffusionTable table;
    table.parameters = expected;
    table.multiple.resize(static_cast<size_t>(expected.cosines) * expected.depths * expected.thicknesses);
    for (size_t k = 0; k < table.multiple.size(); ++k) table.multiple[k] = file.image.rgba[4 * k];
    return table;
}

}  // namespace firmament
