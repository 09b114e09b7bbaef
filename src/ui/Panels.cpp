#include "ui/Panels.h"

#include "ui/Controls.h"
#include "ui/SettingsEditor.h"

#include <imgui.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <string>

namespace firmament {

namespace {

const SettingsSection& section(const std::vector<SettingsSection>& sections, std::string_view name) {
    return *std::find_if(sections.begin(), sections.end(), [&](const SettingsSection& s) { return s.name == name; });
}

void atmosphereProgress(const GuiModel& m) {
    if (!m.atmosphereProgress) return;
    ImGui::ProgressBar(static_cast<float>(*m.atmosphereProgress), ImVec2(-1, 0), "Computing the atmosphere's tables");
}

void basicPanel(GuiModel& m, const std::vector<SettingsSection>& sections, GuiRequests& requests) {
    requests.toggleFullScreen = ImGui::Button("Full screen");
    ImGui::SameLine();
    editSection(section(sections, "display"), {"vsync"});
    editSection(section(sections, "scene"));
    editSection(section(sections, "atmosphere"), {"enabled"});
    editSection(section(sections, "terrain"), {"enabled"});
    editSection(section(sections, "shadows"), {"enabled", "resolution"});
    ImGui::SeparatorText("Sun");
    editSection(section(sections, "sun"));
    editSection(section(sections, "atmosphere"), {"sunIntensity"});
    ImGui::TextDisabled("Right mouse drag turns the sun.");
    atmosphereProgress(m);
}

void additionalPanel(GuiModel& m, const std::vector<SettingsSection>& sections, GuiRequests& requests) {
    ImGui::SeparatorText("Atmosphere");
    const AtmosphereSettings& atmosphere = m.state.atmosphere;
    const bool comparing = atmosphere.comparison != ModelComparison::None;
    editSection(section(sections, "atmosphere"), {"model", "comparison"});
    // Each model's own controls, shown while it draws.
    if (atmosphere.model == AtmosphereModel::Yusov2013 || comparing)
        editSection(section(sections, "atmosphere"), {"singleScattering", "multipleScattering", "integrationSteps"});
    if (atmosphere.model == AtmosphereModel::Bruneton2008 || comparing) editSection(section(sections, "atmosphere"), {"groundAlbedo"});
    editSection(section(sections, "atmosphere"), {"scatteringOrders", "aerosolDensity", "aerosolAbsorption", "mieAsymmetry", "customCoefficients",
                                                   "ozone", "lutResolution", "animateSun"});
    if (m.state.atmosphere.customCoefficients) editSection(section(sections, "atmosphere"), {"rayleighColour", "mieColour"});
    atmosphereProgress(m);
    ImGui::SeparatorText("Shadows");
    editSection(section(sections, "shadows"), {"cascades", "showCascades", "smoothShadows", "bestCascadeSearch", "partitioningFactor", "distanceKm"});
    ImGui::SeparatorText("Terrain");
    editSection(section(sections, "terrain"), {"view", "cameraClearance"});
    ImGui::SeparatorText("Camera");
    editSection(section(sections, "camera"));
    ImGui::SeparatorText("Flight");
    editSection(section(sections, "flight"));
    ImGui::SeparatorText("Devices");
    editSection(section(sections, "devices"));
    if (m.devices.empty()) ImGui::TextDisabled("No HID device or game pad connected.");
    for (const std::string& device : m.devices) ImGui::BulletText("%s", device.c_str());
    ImGui::SeparatorText("Shaders");
    if (m.shaderCompiler.empty()) {
        ImGui::TextDisabled("Hot reload is off (no shader compiler).");
    } else {
        ImGui::TextWrapped("Compiler: %s", m.shaderCompiler.c_str());
        editSection(section(sections, "shaders"));
        requests.reloadShaders = ImGui::Button("Reload shaders (F8)");
    }
    ImGui::SeparatorText("State");
    requests.saveState = ImGui::Button("Save (F5)");
    ImGui::SameLine();
    requests.loadState = ImGui::Button("Load (F9)");
}

// What the selected operator reads of the controls, in one line.
std::string operatorControls(ToneMapOperator op) {
    std::string uses = "Uses the middle gray";
    if (usesWhitePoint(op)) uses += ", the white point";
    if (usesLuminanceSaturation(op)) uses += ", the luminance saturation";
    uses += usesLuminanceSaturation(op) ? "; maps luminance." : "; maps each channel.";
    if (op == ToneMapOperator::FilmicAlu) uses += " Its curve includes the display gamma.";
    return uses;
}

void toneMappingPanel(GuiModel& m, const std::vector<SettingsSection>& sections) {
    const ToneMappingSettings& t = m.state.toneMapping;
    editSection(section(sections, "toneMapping"), {"operator", "middleGray", "whitePoint", "luminanceSaturation"});
    ImGui::TextDisabled("%s", operatorControls(t.op).c_str());
    ImGui::SeparatorText("Exposure");
    editSection(section(sections, "toneMapping"), {"autoExposure", "lightAdaptation", "adaptationSeconds", "exposure"});
    if (!t.autoExposure) {
        ImGui::TextWrapped("Manual: radiance x %.4g (2^EV). The middle gray applies with auto exposure.", m.exposure.exposure);
    } else if (m.exposure.measured) {
        ImGui::Text("Adapted average luminance %.4g", m.exposure.averageLuminance);
        ImGui::Text("Exposure x %.4g (%+.2f EV)", m.exposure.exposure, std::log2(m.exposure.exposure));
    } else {
        ImGui::TextDisabled("Measuring the average luminance...");
    }
}

void performancePanel(GuiModel& m) {
    const auto samples = m.frameTimes.ordered();
    const float top = std::max(m.frameTimes.maximum() * 1.2f, 1.0f);
    char overlay[64];
    std::snprintf(overlay, sizeof(overlay), "CPU frame %.2f ms", m.stats.cpuFrameMs);
    ImGui::PlotLines("##frame times", samples.data(), static_cast<int>(samples.size()), 0, overlay, 0.0f, top, ImVec2(-1, 80));
    ImGui::Text("0 to %.1f ms over the last %zu frames", top, samples.size());
    if (ImGui::BeginTable("passes", 4, ImGuiTableFlags_SizingFixedFit | ImGuiTableFlags_RowBg)) {
        ImGui::TableSetupColumn("GPU pass");
        ImGui::TableSetupColumn("last ms");
        ImGui::TableSetupColumn("mean ms");
        ImGui::TableSetupColumn("max ms");
        ImGui::TableHeadersRow();
        for (const PassTiming& t : m.timings) {
            ImGui::TableNextRow();
            ImGui::TableNextColumn();
            ImGui::TextUnformatted(t.name.c_str());
            if (!t.frames) continue;
            ImGui::TableNextColumn();
            ImGui::Text("%7.3f", t.lastMs);
            ImGui::TableNextColumn();
            ImGui::Text("%7.3f", t.meanMs);
            ImGui::TableNextColumn();
            ImGui::Text("%7.3f", t.maxMs);
        }
        ImGui::EndTable();
    }
}

void shaderErrorWindow(const std::map<std::string, std::string>& errors) {
    if (errors.empty()) return;
    const ImVec2 display = ImGui::GetIO().DisplaySize;
    ImGui::SetNextWindowPos(ImVec2(display.x - 10.0f, display.y - 10.0f), ImGuiCond_Always, ImVec2(1.0f, 1.0f));
    ImGui::SetNextWindowSizeConstraints(ImVec2(300, 0), ImVec2(display.x * 0.6f, display.y * 0.5f));
    ImGui::PushStyleColor(ImGuiCol_WindowBg, ImVec4(0.35f, 0.05f, 0.05f, 0.92f));
    if (ImGui::Begin("Shader errors (the previous shaders are still running)", nullptr,
                     ImGuiWindowFlags_AlwaysAutoResize | ImGuiWindowFlags_NoSavedSettings | ImGuiWindowFlags_NoFocusOnAppearing)) {
        for (const auto& [technique, message] : errors) {
            ImGui::SeparatorText(technique.c_str());
            ImGui::TextUnformatted(message.c_str());
        }
    }
    ImGui::End();
    ImGui::PopStyleColor();
}

void helpWindow(bool& open) {
    if (!open) return;
    const ImVec2 display = ImGui::GetIO().DisplaySize;
    ImGui::SetNextWindowPos(ImVec2(display.x * 0.5f, display.y * 0.5f), ImGuiCond_Appearing, ImVec2(0.5f, 0.5f));
    if (ImGui::Begin("Help", &open, ImGuiWindowFlags_AlwaysAutoResize | ImGuiWindowFlags_NoSavedSettings)) {
        if (ImGui::BeginTable("controls", 2, ImGuiTableFlags_RowBg | ImGuiTableFlags_SizingFixedFit)) {
            for (const ControlBinding& c : kControls) {
                ImGui::TableNextRow();
                ImGui::TableNextColumn();
                ImGui::TextUnformatted(c.input.data(), c.input.data() + c.input.size());
                ImGui::TableNextColumn();
                ImGui::TextUnformatted(c.action.data(), c.action.data() + c.action.size());
            }
            ImGui::EndTable();
        }
    }
    ImGui::End();
}

}  // namespace

GuiRequests drawGui(GuiModel& m) {
    GuiRequests requests;
    const std::vector<SettingsSection> sections = m.state.sections();

    ImGui::SetNextWindowPos(ImVec2(10, 10), ImGuiCond_Always);
    ImGui::SetNextWindowSize(ImVec2(470, 0), ImGuiCond_Always);
    ImGui::SetNextWindowBgAlpha(0.75f);
    if (ImGui::Begin("Firmament", nullptr, ImGuiWindowFlags_NoSavedSettings | ImGuiWindowFlags_NoMove | ImGuiWindowFlags_NoResize)) {
        ImGui::TextUnformatted(m.stats.adapter.c_str());
        ImGui::Text("%d x %d   %.2f ms   %.1f fps", m.stats.width, m.stats.height, m.stats.cpuFrameMs, m.stats.framesPerSecond);
        ImGui::PushItemWidth(-50);  // room for the label
        editSection(section(sections, "ui"), {"panel"});
        ImGui::PopItemWidth();
        ImGui::PushItemWidth(190);
        switch (m.state.ui.panel) {
            case Panel::Basic: basicPanel(m, sections, requests); break;
            case Panel::Additional: additionalPanel(m, sections, requests); break;
            case Panel::ToneMapping: toneMappingPanel(m, sections); break;
            case Panel::Performance: performancePanel(m); break;
        }
        ImGui::PopItemWidth();
        if (!m.notice.empty()) {
            ImGui::Separator();
            ImGui::PushStyleColor(ImGuiCol_Text, m.noticeIsError ? ImVec4(1.0f, 0.45f, 0.4f, 1.0f) : ImVec4(0.6f, 0.9f, 0.6f, 1.0f));
            ImGui::TextWrapped("%s", m.notice.c_str());
            ImGui::PopStyleColor();
        }
        ImGui::TextDisabled("F1: help");
    }
    ImGui::End();

    shaderErrorWindow(m.shaderErrors);
    helpWindow(m.state.ui.help);
    return requests;
}

}  // namespace firmament
