// The atmosphere: light scattering on and off, the sun (Basic panel); the model, the comparison
// of models (and the compared model), each model's own controls while it draws, and the physical
// constants (Additional panel); the tables' progress while they are computed.
#include "ui/panels/TechniquePanels.h"

#include "atmosphere/ModelRegions.h"

#include <imgui.h>

namespace firmament::panels {

namespace {

void progress(const PanelContext& panel) {
    if (!panel.model.atmosphereProgress) return;
    ImGui::ProgressBar(static_cast<float>(*panel.model.atmosphereProgress), ImVec2(-1, 0), "Computing the atmosphere's tables");
}

void basic(PanelContext& panel) {
    editSettings(panel, "atmosphere", {"enabled"});
}

void additional(PanelContext& panel) {
    ImGui::SeparatorText("Atmosphere");
    const AtmosphereSettings& atmosphere = panel.model.state.atmosphere;
    editSettings(panel, "atmosphere", {"model", "comparison"});
    if (atmosphere.comparison == ModelComparison::Split || atmosphere.comparison == ModelComparison::Difference)
        editSettings(panel, "atmosphere", {"comparedModel"});
    if (drawsModel(atmosphere, AtmosphereModel::Yusov2013))
        editSettings(panel, "atmosphere", {"singleScattering", "multipleScattering", "integrationSteps"});
    if (drawsModel(atmosphere, AtmosphereModel::Bruneton2008)) editSettings(panel, "atmosphere", {"groundAlbedo"});
    if (drawsModel(atmosphere, AtmosphereModel::Hillaire2020))
        editSettings(panel, "atmosphere", {"hillaireSkyViewWidth", "hillaireSkyViewHeight", "hillaireSkyViewSteps", "hillaireFroxels",
                                           "hillaireFroxelSteps", "hillaireMultipleScatteringDirections", "hillaireMultipleScatteringSteps",
                                           "hillaireMultipleScatteringDetail"});
    editSettings(panel, "atmosphere", {"scatteringOrders", "aerosolDensity", "aerosolAbsorption", "mieAsymmetry", "customCoefficients", "ozone",
                                       "lutResolution", "animateSun"});
    if (atmosphere.customCoefficients) editSettings(panel, "atmosphere", {"rayleighColour", "mieColour"});
    progress(panel);
}

// The sun sits with the atmosphere: its intensity is the atmosphere's.
void sunBasic(PanelContext& panel) {
    ImGui::SeparatorText("Sun");
    editSettings(panel, "sun");
    editSettings(panel, "atmosphere", {"sunIntensity"});
    ImGui::TextDisabled("Right mouse drag turns the sun.");
    progress(panel);
}

}  // namespace

TechniquePanel atmosphere() { return {basic, additional}; }
TechniquePanel sun() { return {sunBasic, nullptr}; }

}  // namespace firmament::panels
