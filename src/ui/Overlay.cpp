#include "ui/Overlay.h"

#include "core/Error.h"
#include "ui/Controls.h"

#include <imgui.h>
#include <imgui_impl_dx11.h>
#include <imgui_impl_win32.h>

// Declared by the backend's header only behind a comment, by design.
extern IMGUI_IMPL_API LRESULT ImGui_ImplWin32_WndProcHandler(HWND hwnd, UINT msg, WPARAM wParam, LPARAM lParam);

namespace firmament {

Overlay::Overlay(HWND window, ID3D11Device* device, ID3D11DeviceContext* context) {
    IMGUI_CHECKVERSION();
    ImGui::CreateContext();
    ImGuiIO& io = ImGui::GetIO();
    io.IniFilename = nullptr;  // the same layout every run: captures stay reproducible
    ImGui::StyleColorsDark();
    if (!ImGui_ImplWin32_Init(window) || !ImGui_ImplDX11_Init(device, context)) {
        ImGui::DestroyContext();
        throw Error("Dear ImGui could not start on this window and device");
    }
}

Overlay::~Overlay() {
    ImGui_ImplDX11_Shutdown();
    ImGui_ImplWin32_Shutdown();
    ImGui::DestroyContext();
}

bool Overlay::handleMessage(HWND hwnd, UINT message, WPARAM wParam, LPARAM lParam) {
    return ImGui::GetCurrentContext() && ImGui_ImplWin32_WndProcHandler(hwnd, message, wParam, lParam) != 0;
}

bool Overlay::wantsKeyboard() const { return ImGui::GetIO().WantCaptureKeyboard; }

void Overlay::build(const FrameStats& stats, const std::vector<PassTiming>& timings) {
    ImGui_ImplDX11_NewFrame();
    ImGui_ImplWin32_NewFrame();
    ImGui::NewFrame();

    ImGui::SetNextWindowPos(ImVec2(10, 10), ImGuiCond_Always);
    ImGui::SetNextWindowBgAlpha(0.6f);
    const ImGuiWindowFlags overlayFlags = ImGuiWindowFlags_NoDecoration | ImGuiWindowFlags_AlwaysAutoResize |
                                          ImGuiWindowFlags_NoSavedSettings | ImGuiWindowFlags_NoFocusOnAppearing |
                                          ImGuiWindowFlags_NoNav | ImGuiWindowFlags_NoMove;
    if (ImGui::Begin("Frame", nullptr, overlayFlags)) {
        ImGui::Text("%s", stats.adapter.c_str());
        ImGui::Text("%d x %d   %.2f ms CPU frame   %.1f fps", stats.width, stats.height, stats.cpuFrameMs,
                    stats.framesPerSecond);
        if (ImGui::BeginTable("passes", 2, ImGuiTableFlags_SizingFixedFit)) {
            for (const PassTiming& t : timings) {
                ImGui::TableNextRow();
                ImGui::TableNextColumn();
                ImGui::TextUnformatted(t.name.c_str());
                ImGui::TableNextColumn();
                if (t.frames) ImGui::Text("%7.3f ms GPU", t.lastMs);
                else ImGui::TextUnformatted("    ... ms GPU");
            }
            ImGui::EndTable();
        }
        ImGui::TextDisabled("F1: help");
    }
    ImGui::End();

    if (showHelp_) {
        ImGui::SetNextWindowPos(ImVec2(ImGui::GetIO().DisplaySize.x * 0.5f, ImGui::GetIO().DisplaySize.y * 0.5f),
                                ImGuiCond_Appearing, ImVec2(0.5f, 0.5f));
        if (ImGui::Begin("Help", &showHelp_, ImGuiWindowFlags_AlwaysAutoResize | ImGuiWindowFlags_NoSavedSettings)) {
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
    ImGui::Render();
}

void Overlay::render(ID3D11DeviceContext* context, ID3D11RenderTargetView* target) {
    context->OMSetRenderTargets(1, &target, nullptr);
    ImGui_ImplDX11_RenderDrawData(ImGui::GetDrawData());
}

}  // namespace firmament
