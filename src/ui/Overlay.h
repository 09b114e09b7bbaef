#pragma once
// Dear ImGui on the Win32 and Direct3D 11 backends: a small overlay with the frame time and
// the GPU time of every pass, and the F1 help window listing the controls.
#include "gpu/GpuProfiler.h"

#include <d3d11.h>
#include <windows.h>

#include <string>
#include <vector>

namespace firmament {

struct FrameStats {
    double cpuFrameMs = 0.0;
    double framesPerSecond = 0.0;
    int width = 0;
    int height = 0;
    std::string adapter;
};

class Overlay {
public:
    Overlay(HWND window, ID3D11Device* device, ID3D11DeviceContext* context);
    ~Overlay();
    Overlay(const Overlay&) = delete;
    Overlay& operator=(const Overlay&) = delete;

    // Forwards a window message to the GUI; true when the GUI handled it.
    static bool handleMessage(HWND hwnd, UINT message, WPARAM wParam, LPARAM lParam);
    bool wantsKeyboard() const;

    void build(const FrameStats& stats, const std::vector<PassTiming>& timings);
    void render(ID3D11DeviceContext* context, ID3D11RenderTargetView* target);

    void toggleHelp() { showHelp_ = !showHelp_; }
    bool helpVisible() const { return showHelp_; }

private:
    bool showHelp_ = false;
};

}  // namespace firmament
