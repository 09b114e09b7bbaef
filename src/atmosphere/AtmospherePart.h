#pragma once
// The two passes each atmosphere model draws (shaders/atmosphere/<model>/render.hlsl): the sky
// where nothing was drawn (ps_sky), and the aerial perspective over geometry
// (ps_aerial_perspective), which reads a copy of the frame and which the light shafts replace.
#include "gpu/ShaderKey.h"

#include <string>

namespace firmament {

enum class AtmospherePart { Sky, AerialPerspective };

// The full-screen vertex shader and the part's pixel shader of a model's render.hlsl.
inline ShaderKey atmosphereVertexShader(const std::string& file) { return {file, "vs_main", "vs_5_0", {}}; }
inline ShaderKey atmospherePixelShader(const std::string& file, AtmospherePart part) {
    return {file, part == AtmospherePart::Sky ? "ps_sky" : "ps_aerial_perspective", "ps_5_0", {}};
}

}  // namespace firmament
