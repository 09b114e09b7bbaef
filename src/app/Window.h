#pragma once
// The Win32 window: creation, the message pump, resize and minimize tracking, and
// borderless full screen on Alt+Enter. Headless runs create it hidden (Dear ImGui's Win32
// backend needs a window) and never show it.
#include <windows.h>

#include <functional>
#include <string>

namespace firmament {

class Window {
public:
    struct Callbacks {
        // Messages go here first; returning true means handled (the GUI took them).
        std::function<bool(HWND, UINT, WPARAM, LPARAM)> preview;
        std::function<void(WPARAM virtualKey)> keyDown;  // key presses (not auto-repeats)
        // Keyboard, mouse and focus messages, for the fly camera's input state.
        std::function<void(UINT, WPARAM, LPARAM)> input;
    };

    Window(const std::wstring& title, int clientWidth, int clientHeight, bool visible, Callbacks callbacks);
    ~Window();
    Window(const Window&) = delete;
    Window& operator=(const Window&) = delete;

    // Handles every pending message; false once the window was closed.
    bool processMessages();

    HWND handle() const { return hwnd_; }
    int clientWidth() const { return width_; }
    int clientHeight() const { return height_; }
    bool minimized() const { return minimized_; }
    bool fullScreen() const { return fullScreen_; }
    void toggleFullScreen();
    void close();

private:
    static LRESULT CALLBACK windowProc(HWND hwnd, UINT message, WPARAM wParam, LPARAM lParam);
    LRESULT handleMessage(UINT message, WPARAM wParam, LPARAM lParam);

    HWND hwnd_ = nullptr;
    HINSTANCE instance_ = nullptr;
    Callbacks callbacks_;
    int width_ = 0;
    int height_ = 0;
    bool minimized_ = false;
    bool closed_ = false;
    bool fullScreen_ = false;
    RECT windowedRect_{};
    LONG windowedStyle_ = 0;
};

}  // namespace firmament
