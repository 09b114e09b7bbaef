#pragma once
// What a pass that lights the ground needs from the atmosphere
// (shaders/terrain/ground_lighting.hlsli): the model whose tables to read, its constant buffers
// and two tables, the sun's transmittance to the top of the atmosphere and the sky's irradiance
// on a horizontal surface, and the columns of the frame they light. The atmosphere hands out one
// per region of the frame (two in its split view, three in the three-way view), and the
// ground is drawn once for each, clipped to its columns: a comparison of models never reaches
// the ground's shaders.
#include <d3d11.h>

namespace firmament {

// The shader's GROUND_LIGHTING.
enum class GroundLightingModel { None = 0, Yusov2013 = 1, Bruneton2008 = 2, Hillaire2020 = 3 };

struct GroundLighting {
    GroundLightingModel model = GroundLightingModel::None;
    ID3D11Buffer* atmosphere = nullptr;                    // AtmosphereConstants (b1)
    ID3D11Buffer* modelConstants = nullptr;                // b2: BrunetonConstants or HillaireConstants; none for Yusov's
    ID3D11ShaderResourceView* sunTransmittance = nullptr;  // Yusov: the net density table; the others: transmittance
    ID3D11ShaderResourceView* skyIrradiance = nullptr;     // Yusov: the ambient sky light table; the others: irradiance
    int firstColumn = 0;                                   // the frame's columns [firstColumn, endColumn) ...
    int endColumn = 1 << 30;                               // ... that these tables light (clipped to the frame)
};

}  // namespace firmament
