// The Clouds panel: the cell grid (rings, their dimension, layers, particle distance), the layer
// (altitude, thickness), the cloudiness, the density map's resolution and the wind, and the view
// of the particles' bounding shapes; the blending (volume-aware or alpha, the pixel-ordering path)
// and what the running path reports, the resolution the clouds are rendered at, the light
// occlusion and the multiple scattering's model, the light-space map and the early exit; the clouds' shadows and how the light shafts see
// them; the renderer (the particles, or the path-traced reference and its paths per frame). The
// grid's size in cells and particles is shown under it.
#include "clouds/CloudField.h"
#include "clouds/CloudGrid.h"
#include "ui/panels/TechniquePanels.h"

#include <imgui.h>

#include <optional>

namespace firmament::panels {

void clouds(PanelContext& panel) {
    const CloudSettings& c = panel.model.state.clouds;
    editSettings(panel, "clouds", {"enabled", "renderer"});
    if (c.renderer == CloudRenderer::PathTracedReference) editSettings(panel, "clouds", {"referencePaths", "referenceStride"});
    const AtmosphereSettings& a = panel.model.state.atmosphere;
    if (c.enabled && a.comparison != ModelComparison::None) ImGui::TextDisabled("The clouds are drawn with one atmosphere model, not a comparison");
    editSettings(panel, "clouds", {"showParticles", "particleDensity"});
    ImGui::SeparatorText("Rendering");
    editSettings(panel, "clouds", {"volumetricBlending", "blendingPath", "downscale", "lightOcclusion", "multipleScattering", "lightTerms",
                                    "lightSpaceResolution", "opacityEarlyExit", "visibilityCulling"});
    if (c.enabled && !panel.model.cloudBlending.empty()) ImGui::TextWrapped("Running: %s", panel.model.cloudBlending.c_str());
    if (const std::optional<double> progress = panel.model.cloudTableProgress)
        ImGui::TextDisabled("Computing the particle tables: %.0f%%", *progress * 100.0);
    ImGui::SeparatorText("Shadows");
    editSettings(panel, "clouds", {"shadows", "shaftsFromClouds"});
    if (c.enabled && c.shadows && c.shaftsFromClouds != ShaftsFromClouds::None && !panel.model.state.lightShafts.enabled)
        ImGui::TextDisabled("Shafts from clouds needs Enable light shafts");
    ImGui::SeparatorText("Layer");
    editSettings(panel, "clouds", {"cloudiness", "altitude", "thickness", "speed", "densityResolution"});
    ImGui::SeparatorText("Cell grid");
    editSettings(panel, "clouds", {"rings", "ringDimension", "maxLayers", "particleDistance"});
    if (c.effectiveRingDimension() != c.ringDimension) ImGui::TextDisabled("Ring dimension: %d used (a multiple of 4)", c.effectiveRingDimension());
    const CloudGrid grid(c.rings, c.effectiveRingDimension(), c.particleDistance);
    ImGui::TextDisabled("%lld cells; inner cells %.0f m, outer %.0f m; room for %u particles",
                        CloudGrid::cellCount(c.rings, c.effectiveRingDimension()), grid.cellSize(0), grid.cellSize(c.rings - 1),
                        cloudParticleCapacity(c));
}

}  // namespace firmament::panels
