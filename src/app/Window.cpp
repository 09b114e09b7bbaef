#include "app/Window.h"

#include "gpu/Hresult.h"

namespace firmament {

namespace {
constexpr wchar_t kClassName[] = L"FirmamentWindow";
constexpr DWORD kWindowedStyle = WS_OVERLAPPEDWINDOW;
}  // namespace

Window::Window(const std::wstring& title, int clientWidth, int clientHeight, bool visible, Callbacks callbacks)
    : instance_(GetModuleHandleW(nullptr)), callbacks_(std::move(callbacks)), width_(clientWidth), height_(clientHeight) {
    WNDCLASSEXW wc{};
    wc.cbSize = sizeof wc;
    wc.style = CS_HREDRAW | CS_VREDRAW;
    wc.lpfnWndProc = &Window::windowProc;
    wc.hInstance = instance_;
    wc.hCursor = LoadCursorW(nullptr, IDC_ARROW);
    wc.lpszClassName = kClassName;
    if (!RegisterClassExW(&wc) && GetLastError() != ERROR_CLASS_ALREADY_EXISTS)
        check(HRESULT_FROM_WIN32(GetLastError()), "RegisterClassExW");

    RECT rect{0, 0, clientWidth, clientHeight};
    AdjustWindowRect(&rect, kWindowedStyle, FALSE);
    hwnd_ = CreateWindowExW(0, kClassName, title.c_str(), kWindowedStyle, CW_USEDEFAULT, CW_USEDEFAULT,
                            rect.right - rect.left, rect.bottom - rect.top, nullptr, nullptr, instance_, this);
    if (!hwnd_) check(HRESULT_FROM_WIN32(GetLastError()), "CreateWindowExW");
    if (visible) {
        ShowWindow(hwnd_, SW_SHOWDEFAULT);
        UpdateWindow(hwnd_);
        RECT client{};
        GetClientRect(hwnd_, &client);  // what the window manager granted
        if (client.right > 0 && client.bottom > 0) {
            width_ = client.right;
            height_ = client.bottom;
        }
    }
}

Window::~Window() {
    if (hwnd_) DestroyWindow(hwnd_);
    UnregisterClassW(kClassName, instance_);
}

bool Window::processMessages() {
    MSG msg{};
    while (PeekMessageW(&msg, nullptr, 0, 0, PM_REMOVE)) {
        if (msg.message == WM_QUIT) closed_ = true;
        TranslateMessage(&msg);
        DispatchMessageW(&msg);
    }
    return !closed_;
}

void Window::close() { closed_ = true; }

void Window::toggleFullScreen() {
    // Borderless full screen over the monitor that holds the window: flip-model friendly,
    // and no display mode change.
    if (!fullScreen_) {
        GetWindowRect(hwnd_, &windowedRect_);
        windowedStyle_ = GetWindowLongW(hwnd_, GWL_STYLE);
        MONITORINFO monitor{};
        monitor.cbSize = sizeof monitor;
        GetMonitorInfoW(MonitorFromWindow(hwnd_, MONITOR_DEFAULTTONEAREST), &monitor);
        SetWindowLongW(hwnd_, GWL_STYLE, static_cast<LONG>(WS_POPUP | WS_VISIBLE));
        const RECT& r = monitor.rcMonitor;
        SetWindowPos(hwnd_, HWND_TOP, r.left, r.top, r.right - r.left, r.bottom - r.top, SWP_FRAMECHANGED | SWP_SHOWWINDOW);
    } else {
        SetWindowLongW(hwnd_, GWL_STYLE, windowedStyle_);
        const RECT& r = windowedRect_;
        SetWindowPos(hwnd_, HWND_NOTOPMOST, r.left, r.top, r.right - r.left, r.bottom - r.top,
                     SWP_FRAMECHANGED | SWP_SHOWWINDOW);
    }
    fullScreen_ = !fullScreen_;
}

LRESULT CALLBACK Window::windowProc(HWND hwnd, UINT message, WPARAM wParam, LPARAM lParam) {
    if (message == WM_NCCREATE) {
        auto* create = reinterpret_cast<CREATESTRUCTW*>(lParam);
        SetWindowLongPtrW(hwnd, GWLP_USERDATA, reinterpret_cast<LONG_PTR>(create->lpCreateParams));
        static_cast<Window*>(create->lpCreateParams)->hwnd_ = hwnd;  // before CreateWindowExW returns
    }
    auto* self = reinterpret_cast<Window*>(GetWindowLongPtrW(hwnd, GWLP_USERDATA));
    if (!self) return DefWindowProcW(hwnd, message, wParam, lParam);
    if (self->callbacks_.preview && self->callbacks_.preview(hwnd, message, wParam, lParam)) return TRUE;
    return self->handleMessage(message, wParam, lParam);
}

LRESULT Window::handleMessage(UINT message, WPARAM wParam, LPARAM lParam) {
    const bool inputMessage = (message >= WM_KEYFIRST && message <= WM_KEYLAST) ||
                              (message >= WM_MOUSEFIRST && message <= WM_MOUSELAST) || message == WM_KILLFOCUS;
    if (inputMessage && callbacks_.input) callbacks_.input(message, wParam, lParam);
    switch (message) {
        case WM_LBUTTONDOWN:
        case WM_RBUTTONDOWN:
            SetCapture(hwnd_);  // a drag keeps turning when the pointer leaves the window
            return 0;
        case WM_LBUTTONUP:
        case WM_RBUTTONUP:
            if (!(wParam & (MK_LBUTTON | MK_RBUTTON))) ReleaseCapture();
            return 0;
        case WM_SIZE:
            minimized_ = wParam == SIZE_MINIMIZED;
            if (!minimized_) {
                width_ = LOWORD(lParam);
                height_ = HIWORD(lParam);
            }
            return 0;
        case WM_SYSKEYDOWN:
            if (wParam == VK_RETURN && (lParam & (1 << 29))) {  // Alt+Enter
                toggleFullScreen();
                return 0;
            }
            break;
        case WM_KEYDOWN:
            if (callbacks_.keyDown && !(lParam & (1 << 30))) callbacks_.keyDown(wParam);  // not auto-repeat
            return 0;
        case WM_MENUCHAR:
            return MAKELRESULT(0, MNC_CLOSE);  // no beep on Alt+Enter
        case WM_CLOSE:
            closed_ = true;
            return 0;
        case WM_DESTROY:
            hwnd_ = nullptr;
            return 0;
        default:
            break;
    }
    return DefWindowProcW(hwnd_, message, wParam, lParam);
}

}  // namespace firmament
