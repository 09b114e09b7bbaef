// The terrain: on and off (Basic panel); its views and the camera's clearance (Additional panel).
#include "ui/panels/TechniquePanels.h"

#include <imgui.h>

namespace firmament::panels {

namespace {
void basic(PanelContext& panel) { editSettings(panel, "terrain", {"enabled"}); }

void additional(PanelContext& panel) {
    ImGui::SeparatorText("Terrain");
    editSettings(panel, "terrain", {"view", "cameraClearance"});
}
}  // namespace

TechniquePanel terrain() { return {basic, additional}; }

}  // namespace firmament::panels
