// The camera, the fly camera's speeds and the HID devices (Additional panel).
#include "ui/panels/TechniquePanels.h"

#include <imgui.h>

namespace firmament::panels {

namespace {
void additional(PanelContext& panel) {
    ImGui::SeparatorText("Camera");
    editSettings(panel, "camera");
    ImGui::SeparatorText("Flight");
    editSettings(panel, "flight");
    ImGui::SeparatorText("Devices");
    editSettings(panel, "devices");
    if (panel.model.devices.empty()) ImGui::TextDisabled("No HID device or game pad connected.");
    for (const std::string& device : panel.model.devices) ImGui::BulletText("%s", device.c_str());
}
}  // namespace

TechniquePanel camera() { return {nullptr, additional}; }

}  // namespace firmament::panels
