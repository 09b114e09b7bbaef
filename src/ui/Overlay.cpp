#include "ui/Overlay.h"

#include "core/Error.h"

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
bool Overlay::wantsMouse() const { return ImGui::GetIO().WantCaptureMouse; }

GuiRequests Overlay::build(GuiModel& model) {
    ImGui_ImplDX11_NewFrame();
    ImGui_ImplWin32_NewFrame();
    ImGui::NewFrame();
    const GuiRequests requests = drawGui(model);
    ImGui::Render();
    return requests;
}

void Overlay::render(ID3D11DeviceContext* context, ID3D11RenderTargetView* target) {
    context->OMSetRenderTargets(1, &target, nullptr);
    ImGui_ImplDX11_RenderDrawData(ImGui::GetDrawData());
}

}  // namespace firmament
