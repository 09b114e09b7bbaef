#pragma once
// Settings of the terrain (section "terrain").
#include "core/Settings.h"

#include <array>
#include <string_view>

namespace firmament {

// What the terrain's pixels show: the lit surface, or one of its inputs for inspection.
enum class TerrainView { Shaded, Albedo, Normals, Levels, CloudShadows };
inline constexpr std::array<std::string_view, 5> kTerrainViewNames{"Shaded", "Albedo", "Normals", "Clipmap levels", "Cloud shadows"};

struct TerrainSettings {
    bool enabled = true;
    TerrainView view = TerrainView::Shaded;
    float cameraClearance = 100.0f;  // metres the camera keeps above the ground (Yusov 2013's sample: 100)

    void visit(SettingsVisitor& v) {
        v.field("enabled", enabled, "Terrain");
        v.choice("view", view, kTerrainViewNames, "Terrain view");
        v.field("cameraClearance", cameraClearance, {0.0f, 1000.0f}, "Camera clearance (m)");
    }
};

}  // namespace firmament
