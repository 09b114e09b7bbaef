// The light shafts: on and off, the technique and the epipolar sampling's controls, the
// scattering scale and "Lighting only" (Basic panel); the cascade the march starts at, the
// extinction's evaluation, the refinement criterion, the min/max trees' format and the cascade
// processing mode (Additional panel). They need Yusov 2013's model drawn alone: the
// panel says so when another model or a comparison is chosen.
#include "ui/panels/TechniquePanels.h"

#include <imgui.h>

namespace firmament::panels {

namespace {
void basic(PanelContext& panel) {
    editSettings(panel, "lightShafts", {"enabled"});
    const LightShaftSettings& shafts = panel.model.state.lightShafts;
    if (!shafts.enabled) return;
    editSettings(panel, "lightShafts", {"technique"});
    // The epipolar sampling's controls, shown while it draws.
    if (shafts.technique == LightShaftTechnique::Epipolar) {
        editSettings(panel, "lightShafts", {"slices", "samplesPerSlice", "initialStep", "epipoleDensity", "refinementThreshold", "showSampling",
                                            "minMaxOptimization", "optimizeSampleLocations", "correctDepthBreaks", "showDepthBreaks"});
        if (shafts.effectiveInitialStep() != shafts.initialStep)
            ImGui::TextDisabled("Initial sample step: %d used (at most samples / 8)", shafts.effectiveInitialStep());
    }
    editSettings(panel, "lightShafts", {"scatteringScale", "lightingOnly"});
    const AtmosphereSettings& a = panel.model.state.atmosphere;
    if (a.model != AtmosphereModel::Yusov2013 || a.comparison != ModelComparison::None)
        ImGui::TextDisabled("Light shafts need the Yusov 2013 model, not compared");
}

void additional(PanelContext& panel) {
    ImGui::SeparatorText("Light shafts");
    editSettings(panel, "lightShafts", {"firstCascade"});
    if (panel.model.state.lightShafts.technique == LightShaftTechnique::Epipolar) {
        editSettings(panel, "lightShafts", {"extinction", "refinementCriterion", "minMaxFormat", "cascadeProcessing"});
        const State& state = panel.model.state;
        const int marched = state.shadows.cascades - state.lightShafts.firstCascade;
        if (state.lightShafts.effectiveCascadeProcessing(marched) != state.lightShafts.cascadeProcessing)
            ImGui::TextDisabled("Over %lld sample-cascades: single pass used", kMaxCascadeParts);
    }
}
}  // namespace

TechniquePanel lightShafts() { return {basic, additional}; }

}  // namespace firmament::panels
