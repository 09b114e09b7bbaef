// The program's input bindings (App.h): the keys (F1 help, F5 and F9 the state file, F8 hot
// reload, F12 a shot, Escape, the bookmarks on 1 to 9 and Ctrl), the mouse and keyboard handed
// to the fly camera unless the GUI wants them, the GUI's requests, and the notice line that
// answers each.
#include "app/App.h"

#include "core/Error.h"
#include "core/Log.h"
#include "core/SettingsJson.h"

#include <optional>
#include <string>
#include <utility>

namespace firmament {

namespace {

std::optional<int> digitKey(WPARAM key) {
    if (key >= '1' && key <= '9') return static_cast<int>(key - '0');
    if (key >= VK_NUMPAD1 && key <= VK_NUMPAD9) return static_cast<int>(key - VK_NUMPAD0);
    return std::nullopt;
}

}  // namespace

void App::setNotice(std::string text, bool isError) {
    notice_ = std::move(text);
    noticeIsError_ = isError;
}

void App::onInput(UINT message, WPARAM wParam, LPARAM lParam) {
    // (No GUI while the device resources are being made: at start-up and after a device loss.)
    const bool gui = gpu_ && gpu_->overlay;
    keyboardMouse_.onMessage(message, wParam, lParam, gui && gpu_->overlay->wantsMouse(), gui && gpu_->overlay->wantsKeyboard());
}

void App::onKey(WPARAM key) {
    if (gpu_ && gpu_->overlay && gpu_->overlay->wantsKeyboard()) return;
    const bool control = GetKeyState(VK_CONTROL) < 0;
    if (const auto slot = digitKey(key)) {
        if (control) {
            state_.storeBookmark(*slot);
            setNotice("bookmark " + std::to_string(*slot) + " stored", false);
        } else if (state_.recallBookmark(*slot)) {
            setNotice("bookmark " + std::to_string(*slot) + " recalled", false);
        } else {
            setNotice("bookmark " + std::to_string(*slot) + " is empty (Ctrl+" + std::to_string(*slot) + " stores one)", true);
        }
        return;
    }
    switch (key) {
        case VK_F1: state_.ui.help = !state_.ui.help; break;
        case VK_F5: saveState(); break;
        case VK_F8: reloadShaders(); break;
        case VK_F9: loadState(); break;
        case VK_F12: shotRequested_ = true; break;
        case VK_ESCAPE: window_->close(); break;
        default: break;
    }
}

void App::reloadShaders() {
    if (!gpu_->shaders.hotReloadEnabled()) {
        setNotice("shader hot reload is off (see the log)", true);
        return;
    }
    const ReloadResult result = gpu_->shaders.reloadAll();
    if (result.failedTechniques.empty())
        setNotice("reloaded " + std::to_string(result.shadersCompiled) + " shaders in " + std::to_string(static_cast<int>(result.milliseconds)) +
                      " ms" + (result.shadersInBackground ? " (" + std::to_string(result.shadersInBackground) + " more in the background)" : ""),
                  false);
    else
        setNotice("shader reload failed for " + std::to_string(result.failedTechniques.size()) + " technique(s): see the error window", true);
}

void App::saveState() {
    try {
        saveStateFile(state_, options_.stateFile);
        setNotice("state saved to " + options_.stateFile.string(), false);
        log::info("state saved to " + options_.stateFile.string());
    } catch (const Error& e) {
        setNotice(e.what(), true);
        log::error(e.what());
    }
}

void App::loadState() {
    try {
        loadStateFile(state_, options_.stateFile);
        setNotice("state loaded from " + options_.stateFile.string(), false);
        log::info("state loaded from " + options_.stateFile.string());
    } catch (const Error& e) {
        setNotice(e.what(), true);  // the state is unchanged
        log::error(e.what());
    }
}

void App::handleRequests(const GuiRequests& requests) {
    if (requests.toggleFullScreen && gpu_->swapChain) window_->toggleFullScreen();
    if (requests.reloadShaders) reloadShaders();
    if (requests.saveState) saveState();
    if (requests.loadState) loadState();
}

}  // namespace firmament
