#pragma once
// Settings of the step from HDR radiance to the display (section "toneMapping"). Today a
// manual exposure before display encoding; the tone mapping operators, auto exposure and
// light adaptation add their fields here.
#include "core/Settings.h"

#include <cmath>

namespace firmament {

struct ToneMappingSettings {
    float exposureEv = 0.0f;  // exposure value: radiance is scaled by 2^EV

    float exposureScale() const { return std::exp2(exposureEv); }
    void visit(SettingsVisitor& v) { v.field("exposure", exposureEv, {-10.0f, 10.0f}, "Exposure (EV)"); }
};

}  // namespace firmament
