#include "ui/Panels.h"

#include "ui/Controls.h"
#include "ui/PanelContext.h"
#include "ui/panels/TechniquePanels.h"

#include <imgui.h>

namespace firmament {

namespace {

// The techniques' sections of the Basic and Additional panels, in the order they are drawn.
const panels::TechniquePanel kTechniques[] = {panels::display(), panels::scene(),  panels::atmosphere(), panels::terrain(),
                                             panels::shadows(), panels::lightShafts(), panels::sun(), panels::camera(), panels::shaders()};

void basicPanel(PanelContext& panel) {
    for (const panels::TechniquePanel& t : kTechniques)
        if (t.basic) t.basic(panel);
}

void additionalPanel(PanelContext& panel) {
    for (const panels::TechniquePanel& t : kTechniques)
        if (t.additional) t.additional(panel);
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
    PanelContext panel{m, sections, requests};

    ImGui::SetNextWindowPos(ImVec2(10, 10), ImGuiCond_Always);
    ImGui::SetNextWindowSize(ImVec2(470, 0), ImGuiCond_Always);
    ImGui::SetNextWindowBgAlpha(0.75f);
    if (ImGui::Begin("Firmament", nullptr, ImGuiWindowFlags_NoSavedSettings | ImGuiWindowFlags_NoMove | ImGuiWindowFlags_NoResize)) {
        ImGui::TextUnformatted(m.stats.adapter.c_str());
        ImGui::Text("%d x %d   %.2f ms   %.1f fps", m.stats.width, m.stats.height, m.stats.cpuFrameMs, m.stats.framesPerSecond);
        ImGui::PushItemWidth(-50);  // room for the label
        editSettings(panel, "ui", {"panel"});
        ImGui::PopItemWidth();
        ImGui::PushItemWidth(190);
        switch (m.state.ui.panel) {
            case Panel::Basic: basicPanel(panel); break;
            case Panel::Additional: additionalPanel(panel); break;
            case Panel::ToneMapping: panels::toneMapping(panel); break;
            case Panel::Clouds: panels::clouds(panel); break;
            case Panel::Performance: panels::performance(panel); break;
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
