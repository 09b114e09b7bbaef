// The Tone mapping panel: the operator and its controls, the exposure and what it is now.
#include "ui/panels/TechniquePanels.h"

#include <imgui.h>

#include <cmath>
#include <string>

namespace firmament::panels {

namespace {
// What the selected operator reads of the controls, in one line.
std::string operatorControls(ToneMapOperator op) {
    std::string uses = "Uses the middle gray";
    if (usesWhitePoint(op)) uses += ", the white point";
    if (usesLuminanceSaturation(op)) uses += ", the luminance saturation";
    uses += usesLuminanceSaturation(op) ? "; maps luminance." : "; maps each channel.";
    if (op == ToneMapOperator::FilmicAlu) uses += " Its curve includes the display gamma.";
    return uses;
}
}  // namespace

void toneMapping(PanelContext& panel) {
    const ToneMappingSettings& t = panel.model.state.toneMapping;
    const ExposureReading& exposure = panel.model.exposure;
    editSettings(panel, "toneMapping", {"operator", "middleGray", "whitePoint", "luminanceSaturation"});
    ImGui::TextDisabled("%s", operatorControls(t.op).c_str());
    ImGui::SeparatorText("Exposure");
    editSettings(panel, "toneMapping", {"autoExposure", "metering"});
    if (t.metering == Metering::Histogram) editSettings(panel, "toneMapping", {"histogramLow", "histogramHigh"});
    editSettings(panel, "toneMapping", {"lightAdaptation", "adaptationSeconds", "exposure"});
    if (!t.autoExposure) {
        ImGui::TextWrapped("Manual: radiance x %.4g (2^EV). The middle gray applies with auto exposure.", exposure.exposure);
    } else if (exposure.measured) {
        ImGui::Text("Adapted average luminance %.4g", exposure.averageLuminance);
        ImGui::Text("Exposure x %.4g (%+.2f EV)", exposure.exposure, std::log2(exposure.exposure));
    } else {
        ImGui::TextDisabled("Measuring the average luminance...");
    }
}

}  // namespace firmament::panels
