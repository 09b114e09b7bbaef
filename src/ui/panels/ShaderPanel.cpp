// Shader hot reload, and saving and loading the whole state (Additional panel).
#include "ui/panels/TechniquePanels.h"

#include <imgui.h>

namespace firmament::panels {

namespace {
void additional(PanelContext& panel) {
    ImGui::SeparatorText("Shaders");
    if (panel.model.shaderCompiler.empty()) {
        ImGui::TextDisabled("Hot reload is off (no shader compiler).");
    } else {
        ImGui::TextWrapped("Compiler: %s", panel.model.shaderCompiler.c_str());
        editSettings(panel, "shaders");
        panel.requests.reloadShaders = ImGui::Button("Reload shaders (F8)");
    }
    ImGui::SeparatorText("State");
    panel.requests.saveState = ImGui::Button("Save (F5)");
    ImGui::SameLine();
    panel.requests.loadState = ImGui::Button("Load (F9)");
}
}  // namespace

TechniquePanel shaders() { return {nullptr, additional}; }

}  // namespace firmament::panels
