#pragma once
// Settings of the atmosphere (section "atmosphere"): the physical parameters a person changes
// (Yusov 2013's Additional panel: aerosol density and absorption, custom scattering colours)
// and the pre-computation's resolution. Changing any of them recomputes the look-up tables.
#include "core/Settings.h"
#include "frame/ScatteringModes.h"

#include <glm/vec3.hpp>

#include <array>
#include <string_view>

namespace firmament {

enum class LutResolution { Small, Medium, Full };
// Which model draws the atmosphere, from the same physical parameters: Yusov's update of Intel's
// sample, Bruneton and Neyret's 2008 model, or Hillaire's 2020 model.
enum class AtmosphereModel { Yusov2013, Bruneton2008, Hillaire2020 };
inline constexpr std::array<std::string_view, 3> kAtmosphereModelNames{"Yusov 2013", "Bruneton 2008", "Hillaire 2020"};
// Models side by side: the model on the left half and the compared model on the right (Split);
// the absolute difference of their radiance (Difference), which tone mapping then shows; or all
// three in thirds, Yusov's, Bruneton's and Hillaire's from the left (Three-way). ModelRegions.h
// gives each its columns.
enum class ModelComparison { None, Split, Difference, ThreeWay };
inline constexpr std::array<std::string_view, 4> kModelComparisonNames{"None", "Split", "Difference", "Three-way"};
inline constexpr std::array<std::string_view, 3> kLutResolutionNames{"Small (8x32x16x8)", "Medium (16x64x32x8)",
                                                                     "Full (32x128x64x16)"};

struct AtmosphereSettings {
    bool enabled = true;             // "Enable light scattering": the sky and aerial perspective
    AtmosphereModel model = AtmosphereModel::Yusov2013;
    ModelComparison comparison = ModelComparison::None;
    AtmosphereModel comparedModel = AtmosphereModel::Bruneton2008;  // the split's right side, the difference's other term
    float groundAlbedo = 0.1f;       // Bruneton's model: the ground's average reflectance (its bounce and its colour)
    SingleScatteringMode singleScattering = SingleScatteringMode::Table;
    MultipleScatteringMode multipleScattering = MultipleScatteringMode::Unoccluded;
    int integrationSteps = 30;       // per ray, in the Integration mode
    int scatteringOrders = 4;        // orders 2..N are pre-computed
    float sunIntensity = 1.0f;       // the sun's irradiance above the atmosphere (relative units)
    float aerosolDensity = 1.0f;     // scales the Mie scattering coefficient
    float aerosolAbsorption = 0.1f;  // Mie extinction = scattering * (1 + this)
    float mieAsymmetry = 0.76f;      // g of the Cornette-Shanks phase function
    bool customCoefficients = false;
    // Custom scattering colours: beta_R = colour * kRayleighColourScale, beta_M = colour *
    // kMieColourScale * aerosol density. The defaults give back the physical coefficients.
    glm::vec3 rayleighColour{0.145015f, 0.337539f, 0.827619f};
    glm::vec3 mieColour{1.0f, 1.0f, 1.0f};
    bool ozone = false;              // an absorbing ozone layer (Bruneton 2017), beyond Yusov 2013
    bool animateSun = false;         // the sun turns about the x axis (SunAnimation.h)
    LutResolution resolution = LutResolution::Full;
    // Hillaire 2020's own controls, the paper's defaults: the tables made each frame (the sky
    // view's texels and steps, the froxels along each axis of the aerial perspective and the
    // steps per slice), and the multiple-scattering table's directions, steps and texels.
    int hillaireSkyViewWidth = 192, hillaireSkyViewHeight = 108;
    int hillaireSkyViewSteps = 30;     // also the steps of a view marched per pixel (from space, beyond the froxels)
    int hillaireFroxels = 32;
    int hillaireFroxelSteps = 2;       // per slice
    int hillaireMultipleScatteringDirections = 64;
    int hillaireMultipleScatteringSteps = 20;
    int hillaireMultipleScatteringDetail = 1;  // the multiple-scattering table's texels along each axis, times the resolution's (1: the paper's 32 x 32 at Full)

    void visit(SettingsVisitor& v) {
        v.field("enabled", enabled, "Enable light scattering");
        v.choice("model", model, kAtmosphereModelNames, "Atmosphere model");
        v.choice("comparison", comparison, kModelComparisonNames, "Compare models");
        v.choice("comparedModel", comparedModel, kAtmosphereModelNames, "Compared with");
        v.field("groundAlbedo", groundAlbedo, {0.0f, 1.0f}, "Ground albedo (Bruneton)");
        v.choice("singleScattering", singleScattering, kSingleScatteringModeNames, "Single scattering mode");
        v.choice("multipleScattering", multipleScattering, kMultipleScatteringModeNames, "Multiple scattering mode");
        v.field("integrationSteps", integrationSteps, {5, 100}, "Num integration steps");
        v.field("scatteringOrders", scatteringOrders, {1, 10}, "Scattering orders (1: single only)");
        v.field("sunIntensity", sunIntensity, {0.01f, 100.0f, true}, "Sun intensity");
        v.field("aerosolDensity", aerosolDensity, {0.1f, 5.0f}, "Aerosol density");
        v.field("aerosolAbsorption", aerosolAbsorption, {0.0f, 5.0f}, "Aerosol absorption");
        v.field("mieAsymmetry", mieAsymmetry, {0.0f, 0.95f}, "Mie asymmetry g");
        v.field("customCoefficients", customCoefficients, "Use custom scattering coefficients");
        v.colour("rayleighColour", rayleighColour, "Rayleigh colour");
        v.colour("mieColour", mieColour, "Mie colour");
        v.field("ozone", ozone, "Ozone layer");
        v.field("animateSun", animateSun, "Animate sun");
        v.choice("lutResolution", resolution, kLutResolutionNames, "LUT resolution");
        v.field("hillaireSkyViewWidth", hillaireSkyViewWidth, {16, 512}, "Sky-view texels, longitude (Hillaire)");
        v.field("hillaireSkyViewHeight", hillaireSkyViewHeight, {16, 512}, "Sky-view texels, latitude (Hillaire)");
        v.field("hillaireSkyViewSteps", hillaireSkyViewSteps, {4, 128}, "Sky-view steps (Hillaire)");
        v.field("hillaireFroxels", hillaireFroxels, {8, 128}, "Aerial perspective froxels per axis (Hillaire)");
        v.field("hillaireFroxelSteps", hillaireFroxelSteps, {1, 16}, "Aerial perspective steps per slice (Hillaire)");
        v.field("hillaireMultipleScatteringDirections", hillaireMultipleScatteringDirections, {16, 1024},
                "Multiple scattering directions (Hillaire)");
        v.field("hillaireMultipleScatteringSteps", hillaireMultipleScatteringSteps, {4, 100}, "Multiple scattering steps (Hillaire)");
        v.field("hillaireMultipleScatteringDetail", hillaireMultipleScatteringDetail, {1, 8}, "Multiple scattering texels, x (Hillaire)");
    }
};

}  // namespace firmament
