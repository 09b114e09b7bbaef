#pragma once
// Every key and mouse binding the program has, for the F1 help window. README.md and
// docs/controls.md list the same; techniques that add bindings add them here.
#include <array>
#include <string_view>

namespace firmament {

struct ControlBinding {
    std::string_view input;
    std::string_view action;
};

inline constexpr std::array kControls{
    ControlBinding{"W / S", "Fly forward / back (along the view)"},
    ControlBinding{"A / D", "Strafe left / right"},
    ControlBinding{"Q / E", "Fly down / up"},
    ControlBinding{"Shift", "Fly faster (flight.boost times)"},
    ControlBinding{"Mouse wheel", "Change the flight speed"},
    ControlBinding{"Left mouse drag", "Turn the camera"},
    ControlBinding{"Right mouse drag", "Turn the sun (direction of the light)"},
    ControlBinding{"Ctrl+1 .. Ctrl+9", "Store camera and sun in a bookmark"},
    ControlBinding{"1 .. 9", "Recall a bookmark"},
    ControlBinding{"F5 / F9", "Save / load the whole state (--state-file)"},
    ControlBinding{"F8", "Reload every shader from the HLSL folder"},
    ControlBinding{"F12", "Capture the frame (PNG and EXR; --capture names them)"},
    ControlBinding{"F1", "Show or hide this help"},
    ControlBinding{"Alt+Enter", "Toggle borderless full screen"},
    ControlBinding{"Esc", "Quit"},
    ControlBinding{"SpaceMouse", "Push to move, tilt and twist to turn"},
    ControlBinding{"Game pad", "Left stick moves, right stick turns, triggers down / up, R1 / RB faster"},
};

}  // namespace firmament
