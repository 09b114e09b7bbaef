// The cascaded shadow maps: on and off, the resolution (Basic panel); the cascades, their
// splits and reach, and the inspection views (Additional panel).
#include "ui/panels/TechniquePanels.h"

#include <imgui.h>

namespace firmament::panels {

namespace {
void basic(PanelContext& panel) { editSettings(panel, "shadows", {"enabled", "resolution"}); }

void additional(PanelContext& panel) {
    ImGui::SeparatorText("Shadows");
    editSettings(panel, "shadows", {"cascades", "showCascades", "smoothShadows", "bestCascadeSearch", "partitioningFactor", "distanceKm"});
}
}  // namespace

TechniquePanel shadows() { return {basic, additional}; }

}  // namespace firmament::panels
