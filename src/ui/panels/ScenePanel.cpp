// The orientation grid (Basic panel).
#include "ui/panels/TechniquePanels.h"

namespace firmament::panels {

namespace {
void basic(PanelContext& panel) { editSettings(panel, "scene", {"orientationGrid"}); }
}  // namespace

TechniquePanel scene() { return {basic, nullptr}; }

}  // namespace firmament::panels
