#pragma once
// Dear ImGui on the Win32 and Direct3D 11 backends: starts and stops it, forwards window
// messages, and draws the GUI of ui/Panels.h into the output target.
#include "ui/Panels.h"

#include <d3d11.h>
#include <windows.h>

namespace firmament {

class Overlay {
public:
    Overlay(HWND window, ID3D11Device* device, ID3D11DeviceContext* context);
    ~Overlay();
    Overlay(const Overlay&) = delete;
    Overlay& operator=(const Overlay&) = delete;

    // Forwards a window message to the GUI; true when the GUI handled it.
    static bool handleMessage(HWND hwnd, UINT message, WPARAM wParam, LPARAM lParam);
    bool wantsKeyboard() const;
    bool wantsMouse() const;

    GuiRequests build(GuiModel& model);
    void render(ID3D11DeviceContext* context, ID3D11RenderTargetView* target);
};

}  // namespace firmament
