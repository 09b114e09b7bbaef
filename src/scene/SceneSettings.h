#pragma once
// Settings of the scene's reference objects (section "scene").
#include "core/Settings.h"

namespace firmament {

struct SceneSettings {
    bool orientationGrid = true;  // a ground plane with 100 m and 1 km lines (OrientationGridPass)

    void visit(SettingsVisitor& v) { v.field("orientationGrid", orientationGrid, "Orientation grid"); }
};

}  // namespace firmament
