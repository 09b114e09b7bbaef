// The light shafts: on and off, and "Lighting only" while they are on (Basic panel); the first cascade the march
// reads (Additional panel). They need Yusov 2013's model drawn alone: the panel says so when
// another model or a comparison is chosen.
#include "ui/panels/TechniquePanels.h"

#include <imgui.h>

namespace firmament::panels {

namespace {
void basic(PanelContext& panel) {
    editSettings(panel, "lightShafts", {"enabled"});
    // The scene left out of the light shafts' pass: shown while that pass draws.
    if (panel.model.state.lightShafts.enabled) editSettings(panel, "lightShafts", {"lightingOnly"});
    const AtmosphereSettings& a = panel.model.state.atmosphere;
    if (panel.model.state.lightShafts.enabled && (a.model != AtmosphereModel::Yusov2013 || a.comparison != ModelComparison::None))
        ImGui::TextDisabled("Light shafts need the Yusov 2013 model, not compared");
}

void additional(PanelContext& panel) {
    ImGui::SeparatorText("Light shafts");
    editSettings(panel, "lightShafts", {"firstCascade"});
}
}  // namespace

TechniquePanel lightShafts() { return {basic, additional}; }

}  // namespace firmament::panels
