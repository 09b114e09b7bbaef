#pragma once
// Settings of the cascaded shadow maps (section "shadows"): Yusov 2013's Basic panel
// (Shadow map resolution) and Additional panel (Num cascades, Show cascades, Smooth shadows,
// Best cascade search, Partitioning factor), with its defaults.
#include "core/Settings.h"
#include "frame/ShadowStructures.h"

#include <array>
#include <string_view>

namespace firmament {

enum class ShadowMapResolution { R512, R1024, R2048, R4096 };
inline constexpr std::array<std::string_view, 4> kShadowMapResolutionNames{"512", "1024", "2048", "4096"};
inline constexpr int shadowMapTexels(ShadowMapResolution r) { return 512 << static_cast<int>(r); }

struct ShadowSettings {
    bool enabled = true;
    ShadowMapResolution resolution = ShadowMapResolution::R1024;
    int cascades = 4;
    bool showCascades = false;
    bool smoothShadows = true;       // 5-tap PCF
    bool bestCascadeSearch = true;   // the smallest cascade a point projects into, not the depth range's
    float partitioningFactor = 0.95f;  // 1: logarithmic splits, 0: uniform
    float distanceKm = 100.0f;       // how far the cascades reach

    void visit(SettingsVisitor& v) {
        v.field("enabled", enabled, "Shadows");
        v.choice("resolution", resolution, kShadowMapResolutionNames, "Shadow map resolution");
        v.field("cascades", cascades, {1, kMaxCascades}, "Num cascades");
        v.field("showCascades", showCascades, "Show cascades");
        v.field("smoothShadows", smoothShadows, "Smooth shadows");
        v.field("bestCascadeSearch", bestCascadeSearch, "Best cascade search");
        v.field("partitioningFactor", partitioningFactor, {0.0f, 1.0f}, "Partitioning factor");
        v.field("distanceKm", distanceKm, {1.0f, 500.0f}, "Shadow distance (km)");
    }
};

}  // namespace firmament
