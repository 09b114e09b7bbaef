#pragma once
// Fills Bruneton and Neyret 2008's tables on the GPU:
//   1. transmittance T(r, mu) to the top of the atmosphere, 2D;
//   2. the sun's direct irradiance on the ground delta E, 2D;
//   3. single in-scattering, Rayleigh and Mie apart, 4D packed into 3D; S starts from it;
//   4. for each order n = 2..N: delta J over the sphere with the ground's bounce, the
//      irradiance delta E the previous order brings to the ground, then delta S along the
//      rays; E += delta E and S += delta S / P_R(nu).
// Shaders: shaders/atmosphere/bruneton/precompute_*.hlsl. Like Yusov's pre-computation
// (YusovPrecomputation), the work is cut into units of a fraction of a second on the
// WARP device, so that a window computes one per frame (StagedComputation).
#include "atmosphere/AtmosphereComputeInputs.h"
#include "atmosphere/AtmosphereParameters.h"
#include "atmosphere/bruneton/BrunetonParameterization.h"
#include "gpu/ConstantBuffer.h"
#include "gpu/ShaderLibrary.h"
#include "atmosphere/AtmosphereStructures.h"
#include "gpu/Texture.h"
#include "tables/StagedComputation.h"

#include <string>

namespace firmament {

// The model's parameters: the physics both models share, its own table sizes and the ground.
struct BrunetonParameters {
    AtmosphereParameters physics;
    atmosphere::bruneton::Dimensions lut;
    double groundAlbedo = 0.1;

    static BrunetonParameters from(const AtmosphereSettings& settings);
    gpu::BrunetonConstants constants(int order = 0) const;
    std::string describe() const;  // everything that changes the tables, as text
};

// The in-scatter table holds its light times this (half floats would round the light of
// deep twilight away; shaders/atmosphere/bruneton/lookup.hlsli's kInscatterScale, the same number,
// says more).
constexpr double kBrunetonInscatterScale = 1e3;

// The tables render.hlsl reads.
struct BrunetonTables {
    Texture2D transmittance;  // R32G32B32A32_FLOAT: (mu, r) -> T to the top
    Texture2D irradiance;     // R32G32B32A32_FLOAT: (mu_s, r) -> the sky's irradiance E per unit sun irradiance
    Texture3D inscatter;      // R16G16B16A16_FLOAT: S times kBrunetonInscatterScale, Rayleigh RGB (all orders, over P_R) and single Mie's red
};

// Changes when the parameters or the pre-computation shaders change (YusovTableFiles' tableKey).
std::string brunetonTableKey(const BrunetonParameters& parameters, ShaderLibrary& shaders);

enum class BrunetonStage { Transmittance, DirectIrradiance, SingleScattering, Initial, ScatteredRadiance, IndirectIrradiance, ScatteringOrder,
                           AccumulateIrradiance, AccumulateInscatter };
// For the log: a stage's name, and the tables' sizes and orders.
std::string stageName(BrunetonStage stage, int order);
std::string describeTables(const BrunetonParameters& parameters);

// What only computing needs: the shaders' inputs and the model's constants (their order changes
// from unit to unit), the deltas of one order, and the running sums E and S, ping-ponged (typed
// UAVs of four channels cannot be read and written in place; one texture of each pair is the
// table itself). The deltas are float32: the higher orders fall far below half's normal range.
struct BrunetonScratch {
    BrunetonScratch(ID3D11Device* device, const BrunetonParameters& parameters, const BrunetonTables& tables);
    AtmosphereComputeInputs inputs;
    ConstantBuffer<gpu::BrunetonConstants> bruneton;
    Texture2D deltaIrradiance, irradianceSums[2];
    Texture3D deltaRayleigh, deltaMie, deltaJ, inscatterSums[2];
};

class BrunetonPrecomputation final : public StagedComputation<BrunetonStage, BrunetonParameters, BrunetonTables, BrunetonScratch> {
public:
    BrunetonPrecomputation(ID3D11Device* device, const BrunetonParameters& parameters);
};

}  // namespace firmament
