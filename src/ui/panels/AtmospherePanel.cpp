// The atmosphere: light scattering on and off, the sun (Basic panel); the model, the comparison
// of models, each model's own controls while it draws, and the physical constants (Additional
// panel); the tables' progress while they are computed.
#include "ui/panels/TechniquePanels.h"

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
    const bool comparing = atmosphere.comparison != ModelComparison::None;
    editSettings(panel, "atmosphere", {"model", "comparison"});
    if (atmosphere.model == AtmosphereModel::Yusov2013 || comparing)
        editSettings(panel, "atmosphere", {"singleScattering", "multipleScattering", "integrationSteps"});
    if (atmosphere.model == AtmosphereModel::Bruneton2008 || comparing) editSettings(panel, "atmosphere", {"groundAlbedo"});
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
