#pragma once
// How the sky's scattering is evaluated at render time, chosen in the atmosphere's settings and
// handed to every technique that looks Yusov 2013's tables up itself (ScatteringLookup.h): the
// light shafts evaluate it the same way as the atmosphere's own passes.
#include <array>
#include <string_view>

namespace firmament {

// Where single scattering comes from at render time (Yusov 2013's Additional panel); the
// order is the shader's mode index (shaders/atmosphere/yusov/render.hlsl).
enum class SingleScatteringMode { None, Integration, Table };
inline constexpr std::array<std::string_view, 3> kSingleScatteringModeNames{"None", "Integration", "LUT"};
// Higher orders (Yusov 2013, "Occluded vs unoccluded"): none; occluded, the multiple
// scattering table alone (single scattering from it too); unoccluded, single scattering as
// its mode says plus the high-order table.
enum class MultipleScatteringMode { None, Occluded, Unoccluded };
inline constexpr std::array<std::string_view, 3> kMultipleScatteringModeNames{"None", "Occluded", "Unoccluded"};

}  // namespace firmament
