#pragma once
// Fills Hillaire 2020's tables that do not depend on the camera, on the GPU:
//   1. transmittance T(r, mu) to the top of the atmosphere, 2D;
//   2. multiple scattering Psi_ms(r, mu_s), 2D, which reads the first;
//   3. the sky's irradiance E(r, mu_s) on a horizontal surface, 2D, from the model's own radiance
//      (both tables above): Firmament's addition, which lights the ground.
// Shaders: shaders/atmosphere/hillaire/precompute_*.hlsl. The sky-view and aerial-perspective
// tables follow the camera and are made each frame (HillairePass). Like the other models'
// pre-computations, the work is cut into units (StagedComputation); these tables are small
// enough for one unit each.
#include "atmosphere/AtmosphereComputeInputs.h"
#include "atmosphere/AtmosphereParameters.h"
#include "atmosphere/AtmosphereStructures.h"
#include "atmosphere/hillaire/HillaireParameterization.h"
#include "gpu/ConstantBuffer.h"
#include "gpu/ShaderLibrary.h"
#include "gpu/Texture.h"
#include "tables/StagedComputation.h"

#include <string>

namespace firmament {

// The model's parameters: the physics the three models share and its own tables' sizes and
// sampling (the paper's: 64 directions of 20 steps for the multiple scattering; the sky
// irradiance's 256 directions of 20 steps are Firmament's).
struct HillaireParameters {
    AtmosphereParameters physics;
    atmosphere::hillaire::Dimensions lut;
    int multipleScatteringDirections = 64;
    int multipleScatteringSteps = 20;
    int irradianceDirections = 256;
    int irradianceSteps = 20;

    static HillaireParameters from(const AtmosphereSettings& settings);

    gpu::HillaireConstants constants() const;
    std::string describe() const;  // everything that changes the tables, as text
};

struct HillaireTables {
    Texture2D transmittance;       // R32G32B32A32_FLOAT: (mu, r) -> T to the top
    Texture2D multipleScattering;  // R32G32B32A32_FLOAT: (mu_s, r) -> Psi_ms per unit sun irradiance
    Texture2D irradiance;          // R32G32B32A32_FLOAT: (mu_s, r) -> E per unit sun irradiance
};

// Changes when the parameters or the pre-computation shaders change (YusovTableFiles' tableKey).
std::string hillaireTableKey(const HillaireParameters& parameters, ShaderLibrary& shaders);

enum class HillaireStage { Transmittance, MultipleScattering, Irradiance };
std::string stageName(HillaireStage stage, int order);
std::string describeTables(const HillaireParameters& parameters);

// What only computing needs: the inputs every model's pre-computation reads (the constants, the
// sampler, and the multiple scattering's directions over the sphere), the sky irradiance's
// directions and the model's constants.
struct HillaireScratch {
    HillaireScratch(ID3D11Device* device, const HillaireParameters& parameters, const HillaireTables& tables);
    AtmosphereComputeInputs inputs;
    Microsoft::WRL::ComPtr<ID3D11ShaderResourceView> irradianceDirections;
    ConstantBuffer<gpu::HillaireConstants> hillaire;
};

class HillairePrecomputation final : public StagedComputation<HillaireStage, HillaireParameters, HillaireTables, HillaireScratch> {
public:
    HillairePrecomputation(ID3D11Device* device, const HillaireParameters& parameters);
};

}  // namespace firmament
