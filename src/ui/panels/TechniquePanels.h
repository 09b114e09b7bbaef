#pragma once
// Each technique's part of the GUI, one file each in ui/panels/: what it shows in the Basic
// panel and in the Additional panel (the layout of Yusov 2013's sample), in the order the
// list in Panels.cpp gives. Adding a technique adds its file, its declaration here and one
// line to that list.
#include "ui/PanelContext.h"

namespace firmament::panels {

// One technique's sections; either may be null.
struct TechniquePanel {
    void (*basic)(PanelContext& panel);
    void (*additional)(PanelContext& panel);
};

TechniquePanel display();     // full screen, VSync (DisplayPanel.cpp)
TechniquePanel scene();       // the orientation grid (ScenePanel.cpp)
TechniquePanel atmosphere();  // scattering on/off, the models, their constants, the sun (AtmospherePanel.cpp)
TechniquePanel shadows();     // the cascades (ShadowPanel.cpp)
TechniquePanel lightShafts(); // shafts on/off, what the march skips and shows (LightShaftPanel.cpp)
TechniquePanel terrain();     // the terrain and its views (TerrainPanel.cpp)
TechniquePanel sun();         // the sun's position and intensity, the tables' progress (AtmospherePanel.cpp)
TechniquePanel camera();      // camera, flight, HID devices (CameraPanel.cpp)
TechniquePanel shaders();     // hot reload, saving and loading the state (ShaderPanel.cpp)

// The whole Tone mapping, Clouds and Performance panels.
void toneMapping(PanelContext& panel);  // ToneMappingPanel.cpp
void clouds(PanelContext& panel);       // CloudPanel.cpp
void performance(PanelContext& panel);  // PerformancePanel.cpp

}  // namespace firmament::panels
