#pragma once
// Draws Hillaire 2020's atmosphere with its tables (shaders/atmosphere/hillaire/render.hlsl), in
// the two parts every model draws (AtmospherePart), after making the two tables that follow the
// camera each frame:
//  - the sky-view table (sky_view.hlsl): the sky from the camera's altitude, by latitude and
//    longitude about the sun;
//  - the aerial-perspective volume (aerial_perspective.hlsl): in-scattering and transmittance in
//    froxels of the camera's frustum.
#include "atmosphere/AtmospherePart.h"
#include "atmosphere/AtmosphereSettings.h"
#include "atmosphere/AtmosphereStructures.h"
#include "atmosphere/hillaire/HillairePrecomputation.h"
#include "gpu/ConstantBuffer.h"
#include "gpu/FullscreenPass.h"
#include "gpu/Texture.h"

namespace firmament {

// What the per-frame tables are made with (AtmosphereSettings' Hillaire controls).
struct HillaireFrameSampling {
    int skyViewWidth = 192, skyViewHeight = 108, skyViewSteps = 30;
    int froxels = 32, froxelSteps = 2;

    static HillaireFrameSampling from(const AtmosphereSettings& settings);
};

// The per-frame tables, for the passes and the tests.
struct HillaireCameraTables {
    Texture2D skyView;               // R32G32B32A32_FLOAT: (longitude, latitude) -> radiance per unit sun irradiance
    Texture3D aerialInscattering;    // R32G32B32A32_FLOAT: froxel -> in-scattered radiance per unit sun irradiance
    Texture3D aerialTransmittance;   // R32G32B32A32_FLOAT: froxel -> transmittance from the camera
};

class HillairePass {
public:
    explicit HillairePass(ID3D11Device* device);

    // The sky-view table and the aerial-perspective volume for the frame's camera and sun.
    void makeCameraTables(ID3D11DeviceContext* context, ShaderLibrary& shaders, const HillairePrecomputation& tables, ID3D11Buffer* frameConstants,
                          const HillaireFrameSampling& sampling);
    // A part, with the tables made last. `sceneRadiance`: a copy of the frame before this pass.
    void render(ID3D11DeviceContext* context, ShaderLibrary& shaders, AtmospherePart part, const HillairePrecomputation& tables,
                ID3D11Buffer* frameConstants, ID3D11ShaderResourceView* sceneRadiance, ID3D11ShaderResourceView* depth, const Texture2D& target,
                Columns columns = {});

    const HillaireCameraTables& cameraTables() const { return camera_; }
    // The model's constants as the passes see them: the tables' sizes and the frame's sampling.
    static gpu::HillaireConstants constants(const HillaireParameters& parameters, const HillaireFrameSampling& sampling);

private:
    ID3D11Device* device_;
    FullscreenPass fullscreen_;
    ConstantBuffer<gpu::AtmosphereConstants> atmosphere_;
    ConstantBuffer<gpu::HillaireConstants> hillaire_;
    ConstantBuffer<gpu::HillairePassConstants> pass_;
    ComPtr<ID3D11SamplerState> linearClamp_;
    HillaireCameraTables camera_;
};

}  // namespace firmament
