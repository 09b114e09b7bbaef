#pragma once
// What a pass that lights the ground needs from the atmosphere (shaders/terrain/ground_lighting.hlsli):
// the model whose tables to read, its constant buffers and the two tables, the sun's
// transmittance to the top of the atmosphere and the sky's irradiance on a horizontal surface.
#include <d3d11.h>

namespace firmament {

// The shader's GROUND_LIGHTING. Split: Yusov's tables left of the middle column, Bruneton's from
// it on, as the atmosphere's split view.
enum class GroundLightingModel { None = 0, Yusov2013 = 1, Bruneton2008 = 2, Split = 3 };

struct GroundLighting {
    GroundLightingModel model = GroundLightingModel::None;
    ID3D11Buffer* atmosphere = nullptr;                    // AtmosphereConstants (b1)
    ID3D11Buffer* bruneton = nullptr;                      // BrunetonConstants (b2), Bruneton's model only
    ID3D11ShaderResourceView* sunTransmittance = nullptr;  // Yusov: the net density table; Bruneton: transmittance
    ID3D11ShaderResourceView* skyIrradiance = nullptr;     // Yusov: the ambient sky light table; Bruneton: irradiance
    ID3D11ShaderResourceView* brunetonTransmittance = nullptr;  // Split: Bruneton's tables for the right side
    ID3D11ShaderResourceView* brunetonIrradiance = nullptr;
};

}  // namespace firmament
