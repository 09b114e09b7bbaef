#pragma once
// Every key and mouse binding the program has, for the F1 help window (and the README's
// controls table, which lists the same). Techniques that add bindings add them here.
#include <array>
#include <string_view>

namespace firmament {

struct ControlBinding {
    std::string_view input;
    std::string_view action;
};

inline constexpr std::array kControls{
    ControlBinding{"F1", "Show or hide this help"},
    ControlBinding{"Alt+Enter", "Toggle borderless full screen"},
    ControlBinding{"Esc", "Quit"},
};

}  // namespace firmament
