// The display: full screen and VSync (Basic panel).
#include "ui/panels/TechniquePanels.h"

#include <imgui.h>

namespace firmament::panels {

namespace {
void basic(PanelContext& panel) {
    panel.requests.toggleFullScreen = ImGui::Button("Full screen");
    ImGui::SameLine();
    editSettings(panel, "display", {"vsync"});
}
}  // namespace

TechniquePanel display() { return {basic, nullptr}; }

}  // namespace firmament::panels
