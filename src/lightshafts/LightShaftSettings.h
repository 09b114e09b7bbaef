#pragma once
// Settings of the light shafts (section "lightShafts"): in-scattering counted only where the
// sun reaches, through the cascaded shadow maps (Yusov 2013; Yusov's GPU Pro 5 chapter). The
// controls of Yusov 2013's Basic and Additional panels for the light shafts
// (docs/lightshafts.md, "Controls").
#include "core/Settings.h"

#include <array>
#include <string_view>

namespace firmament {

inline constexpr int kMaxMarchedCascade = 7;

// "Scattering technique": epipolar sampling, or the brute-force reference that marches every pixel.
enum class LightShaftTechnique { Epipolar, BruteForce };
inline constexpr std::array<std::string_view, 2> kLightShaftTechniqueNames{"Epipolar sampling", "Brute-force ray marching"};
// "Refinement criterion": what decides that two neighbouring samples differ.
enum class RefinementCriterion { Depth, Inscattering };
inline constexpr std::array<std::string_view, 2> kRefinementCriterionNames{"Depth", "In-scattering"};
// "Extinction evaluation mode": the transmittance to the geometry per pixel, or blended from
// the epipolar samples like the in-scattering.
enum class ExtinctionEvaluation { PerPixel, Epipolar };
inline constexpr std::array<std::string_view, 2> kExtinctionEvaluationNames{"Per pixel", "Epipolar"};
// "Min/max format": the 1D min/max trees' texture format.
enum class MinMaxFormat { Unorm16, Float32 };
inline constexpr std::array<std::string_view, 2> kMinMaxFormatNames{"16-bit unorm", "32-bit float"};
// "Cascade processing mode": the march through all cascades in one pass, or cascade by cascade,
// one dispatch each (multi pass) or one dispatch with a layer per cascade (instanced).
enum class CascadeProcessing { SinglePass, MultiPass, Instanced };
inline constexpr std::array<std::string_view, 3> kCascadeProcessingNames{"Single pass", "Multi pass", "Multi pass instanced"};
// The cascade-by-cascade modes keep 32 bytes per listed sample and cascade; beyond this many
// sample-cascades (64 MiB) they fall back to the single pass.
inline constexpr long long kMaxCascadeParts = 2 * 1024 * 1024;
// "Epipolar slices": powers of two from 32 to 2048.
inline constexpr std::array<std::string_view, 7> kSliceCountNames{"32", "64", "128", "256", "512", "1024", "2048"};

struct LightShaftSettings {
    bool enabled = true;  // "Enable light shafts" (with Yusov 2013's model drawn alone)
    LightShaftTechnique technique = LightShaftTechnique::Epipolar;
    int slices = 512;               // "Epipolar slices"
    int samplesPerSlice = 256;      // "Total samples in slice"
    int initialStep = 16;           // "Initial sample step": 1 to samples / 8 (larger values count as samples / 8)
    int epipoleDensity = 2;         // "Epipole sampling density": the initial step's divisor near the epipole
    float refinementThreshold = 0.03f;
    bool showSampling = false;
    bool optimizeSampleLocations = true;
    bool correctDepthBreaks = false;  // "Correction at depth breaks"
    bool showDepthBreaks = false;
    RefinementCriterion refinementCriterion = RefinementCriterion::Inscattering;
    ExtinctionEvaluation extinction = ExtinctionEvaluation::Epipolar;
    bool minMaxOptimization = true;  // "1D min/max optimization": the march walks the trees
    CascadeProcessing cascadeProcessing = CascadeProcessing::SinglePass;
    MinMaxFormat minMaxFormat = MinMaxFormat::Unorm16;
    // "Scattering scale": the light the shafts' passes scatter into the view rays is multiplied
    // by it (the haze and the shafts; not the sun's disc, nor the scene's own light). Yusov's
    // sample scales its sun's colour instead, by 0.5 by default; the Sun intensity control does
    // that here, so the default is 1: the shafts then draw what the atmosphere draws.
    float scatteringScale = 1.0f;
    int firstCascade = 1;        // "First cascade to ray march", from the camera on: its map holds the camera
    bool lightingOnly = false;   // "Lighting only": the in-scattered light alone, no scene, no sun

    // The cascade processing mode the march uses with `marchedCascades` cascades to march: the
    // cascade-by-cascade modes fall back to the single pass beyond kMaxCascadeParts.
    CascadeProcessing effectiveCascadeProcessing(int marchedCascades) const {
        const long long parts = static_cast<long long>(slices) * samplesPerSlice * (marchedCascades > 0 ? marchedCascades : 0);
        return parts > kMaxCascadeParts ? CascadeProcessing::SinglePass : cascadeProcessing;
    }

    // The Depth criterion's threshold: a fifth of the refinement threshold, as in Intel's sample
    // (camera-space depth changes along a slice far more smoothly than the light does, and at
    // the threshold itself the Depth criterion refined too little: docs/lightshafts.md,
    // "Departures from Intel's sample").
    float depthRefinementThreshold() const { return 0.2f * refinementThreshold; }

    // The initial step as the passes use it: at most a eighth of the samples.
    int effectiveInitialStep() const {
        const int most = samplesPerSlice / 8 > 1 ? samplesPerSlice / 8 : 1;
        return initialStep < most ? initialStep : most;
    }

    void visit(SettingsVisitor& v) {
        v.field("enabled", enabled, "Enable light shafts");
        v.choice("technique", technique, kLightShaftTechniqueNames, "Scattering technique");
        int sliceIndex = 0;
        while (sliceIndex < 6 && (32 << sliceIndex) < slices) ++sliceIndex;
        v.choiceIndex("slices", sliceIndex, kSliceCountNames, "Epipolar slices");
        slices = 32 << sliceIndex;
        v.field("samplesPerSlice", samplesPerSlice, {32, 2048}, "Total samples in slice");
        v.field("initialStep", initialStep, {1, 256}, "Initial sample step");
        v.field("epipoleDensity", epipoleDensity, {1, 32}, "Epipole sampling density");
        v.field("refinementThreshold", refinementThreshold, {0.001f, 0.5f, true}, "Refinement threshold");
        v.field("showSampling", showSampling, "Show sampling");
        v.field("optimizeSampleLocations", optimizeSampleLocations, "Optimize sample locations");
        v.field("correctDepthBreaks", correctDepthBreaks, "Correction at depth breaks");
        v.field("showDepthBreaks", showDepthBreaks, "Show depth breaks");
        v.choice("refinementCriterion", refinementCriterion, kRefinementCriterionNames, "Refinement criterion");
        v.choice("extinction", extinction, kExtinctionEvaluationNames, "Extinction evaluation mode");
        v.field("minMaxOptimization", minMaxOptimization, "1D min/max optimization");
        v.choice("minMaxFormat", minMaxFormat, kMinMaxFormatNames, "Min/max format");
        v.choice("cascadeProcessing", cascadeProcessing, kCascadeProcessingNames, "Cascade processing mode");
        v.field("scatteringScale", scatteringScale, {0.1f, 2.0f}, "Scattering scale");
        v.field("firstCascade", firstCascade, {0, kMaxMarchedCascade}, "First cascade to ray march");
        v.field("lightingOnly", lightingOnly, "Lighting only");
    }
};

}  // namespace firmament
