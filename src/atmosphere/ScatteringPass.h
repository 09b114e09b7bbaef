#pragma once
// Applies the atmosphere to the HDR frame (shaders/atmosphere/apply_scattering.hlsl): the sky
// and the sun where there is no geometry, aerial perspective (eq. 8) where there is. It reads
// the frame it writes, so it first copies the frame into a texture of its own.
#include "atmosphere/AtmosphereSettings.h"
#include "atmosphere/ScatteringPrecomputation.h"
#include "gpu/ConstantBuffer.h"
#include "gpu/FullscreenPass.h"
#include "gpu/SharedStructures.h"
#include "gpu/Texture.h"

namespace firmament {

class ScatteringPass {
public:
    explicit ScatteringPass(ID3D11Device* device);

    void render(ID3D11DeviceContext* context, ShaderLibrary& shaders, const AtmosphereSettings& settings,
                const AtmosphereParameters& parameters, const ScatteringTables& tables, ID3D11Buffer* frameConstants,
                ID3D11ShaderResourceView* sceneRadiance, ID3D11ShaderResourceView* depth, const Texture2D& target);

    // The sun's disc: angular radius and radiance per unit irradiance (1 / its solid angle).
    static constexpr double kSunAngularRadius = 0.00465;  // radians: 0.2666 degrees, as seen from the Earth
    static double sunDiscRadiance();

private:
    FullscreenPass fullscreen_;
    ConstantBuffer<gpu::AtmosphereConstants> atmosphere_;
    ConstantBuffer<gpu::ScatteringPassConstants> constants_;
    ComPtr<ID3D11SamplerState> linearClamp_;
};

}  // namespace firmament
