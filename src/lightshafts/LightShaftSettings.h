#pragma once
// Settings of the light shafts (section "lightShafts"): in-scattering counted only where the
// sun reaches, through the cascaded shadow maps (Yusov 2013; Yusov's GPU Pro 5 chapter). The
// controls of Yusov 2013's Basic and Additional panels that the brute-force ray marching uses;
// the epipolar sampling's own controls arrive with it (docs/lightshafts.md).
#include "core/Settings.h"

namespace firmament {

inline constexpr int kMaxMarchedCascade = 7;

struct LightShaftSettings {
    // "Enable light shafts". Off by default until the epipolar sampling lands: the brute-force
    // reference marches every pixel, seconds per frame at 1280x720 on a CPU device.
    bool enabled = false;
    int firstCascade = 1;        // "First cascade to ray march": the finer ones count as lit
    bool lightingOnly = false;   // "Lighting only": the in-scattered light alone, no scene, no sun

    void visit(SettingsVisitor& v) {
        v.field("enabled", enabled, "Enable light shafts");
        v.field("firstCascade", firstCascade, {0, kMaxMarchedCascade}, "First cascade to ray march");
        v.field("lightingOnly", lightingOnly, "Lighting only");
    }
};

}  // namespace firmament
