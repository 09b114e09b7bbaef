// The Performance panel: the CPU frame times and every pass's GPU time.
#include "ui/panels/TechniquePanels.h"

#include <imgui.h>

#include <algorithm>
#include <cstdio>

namespace firmament::panels {

void performance(PanelContext& panel) {
    const GuiModel& m = panel.model;
    const auto samples = m.frameTimes.ordered();
    const float top = std::max(m.frameTimes.maximum() * 1.2f, 1.0f);
    char overlay[64];
    std::snprintf(overlay, sizeof(overlay), "CPU frame %.2f ms", m.stats.cpuFrameMs);
    ImGui::PlotLines("##frame times", samples.data(), static_cast<int>(samples.size()), 0, overlay, 0.0f, top, ImVec2(-1, 80));
    ImGui::Text("0 to %.1f ms over the last %zu frames", top, samples.size());
    if (!ImGui::BeginTable("passes", 4, ImGuiTableFlags_SizingFixedFit | ImGuiTableFlags_RowBg)) return;
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

}  // namespace firmament::panels
