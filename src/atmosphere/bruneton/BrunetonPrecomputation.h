#pragma once
// Fills Bruneton and Neyret 2008's tables on the GPU (document 002):
//   1. transmittance T(r, mu) to the top of the atmosphere, 2D;
//   2. the sun's direct irradiance on the ground delta E, 2D;
//   3. single in-scattering, Rayleigh and Mie apart, 4D packed into 3D; S starts from it;
//   4. for each order n = 2..N: delta J over the sphere with the ground's bounce, the
//      irradiance delta E the previous order brings to the ground, then delta S along the
//      rays; E += delta E and S += delta S / P_R(nu).
// Shaders: shaders/atmosphere/bruneton/precompute_*.hlsl. Like Yusov's pre-computation
// (ScatteringPrecomputation), the work is cut into units of a fraction of a second on the
// WARP device, so that a window computes one per frame.
#include "atmosphere/AtmosphereParameters.h"
#include "atmosphere/PrecomputationSupport.h"
#include "atmosphere/bruneton/BrunetonParameterization.h"
#include "gpu/ConstantBuffer.h"
#include "gpu/ShaderLibrary.h"
#include "gpu/SharedStructures.h"

#include <string>
#include <vector>

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

// The tables render.hlsl reads.
struct BrunetonTables {
    Texture2D transmittance;  // R32G32B32A32_FLOAT: (mu, r) -> T to the top
    Texture2D irradiance;     // R32G32B32A32_FLOAT: (mu_s, r) -> the sky's irradiance E per unit sun irradiance
    Texture3D inscatter;      // R16G16B16A16_FLOAT: S, Rayleigh RGB (all orders, over P_R) and single Mie's red
};

// Changes when the parameters or the pre-computation shaders change (ScatteringTableFiles' tableKey).
std::string brunetonTableKey(const BrunetonParameters& parameters, ShaderLibrary& shaders);

class BrunetonPrecomputation {
public:
    BrunetonPrecomputation(ID3D11Device* device, const BrunetonParameters& parameters);

    bool step(ID3D11DeviceContext* context, ShaderLibrary& shaders);  // false once everything has run
    void runAll(ID3D11DeviceContext* context, ShaderLibrary& shaders);
    bool done() const { return next_ >= units_.size(); }
    double progress() const { return units_.empty() ? 1.0 : static_cast<double>(next_) / static_cast<double>(units_.size()); }
    std::string currentStage() const;
    // The tables were filled another way (from files): nothing is left to run.
    void markComplete() {
        next_ = units_.size();
        releaseScratch();
    }

    const BrunetonTables& tables() const { return tables_; }
    const BrunetonParameters& parameters() const { return parameters_; }

private:
    enum class Stage { Transmittance, DirectIrradiance, SingleScattering, Initial, ScatteredRadiance, IndirectIrradiance, ScatteringOrder,
                       AccumulateIrradiance, AccumulateInscatter };
    struct Unit {
        Stage stage;
        unsigned first, end;  // radius layers of the 4D tables
        int order;
    };
    void run(ID3D11DeviceContext* context, ShaderLibrary& shaders, const Unit& unit);
    void allocateScratch();
    void releaseScratch();

    ID3D11Device* device_;
    BrunetonParameters parameters_;
    BrunetonTables tables_;
    // Only while computing. The sums E and S are ping-ponged (typed UAVs of four channels cannot
    // be read and written in place); one texture of each pair is the table itself.
    Texture2D deltaIrradiance_;
    Texture2D irradianceSums_[2];
    Texture3D deltaRayleigh_, deltaMie_, deltaJ_;  // float32: the higher orders fall far below half's normal range
    Texture3D inscatterSums_[2];
    ComPtr<ID3D11ShaderResourceView> sphereDirectionsView_;
    ConstantBuffer<gpu::AtmosphereConstants> atmosphere_;
    ConstantBuffer<gpu::BrunetonConstants> bruneton_;
    ConstantBuffer<gpu::PrecomputeSliceConstants> slab_;
    ComPtr<ID3D11SamplerState> linearClamp_;
    std::vector<Unit> units_;
    size_t next_ = 0;
};

}  // namespace firmament
