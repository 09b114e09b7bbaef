#pragma once
// Fills the atmosphere's look-up tables on the GPU (document 000, frame order step 1):
//   1. net density to the top of the atmosphere, 2D (shaders/atmosphere/precompute_net_density.hlsl);
//   2. single scattering, 4D packed into 3D (precompute_single_scattering.hlsl).
// The work is cut into units (blocks of rows, slabs of z slices) of a fraction of a second each
// on the WARP device, so that a recompute can run one unit per frame and the window stays
// responsive; runAll() does everything at once, with progress in the log.
#include "atmosphere/AtmosphereParameters.h"
#include "gpu/ConstantBuffer.h"
#include "gpu/ShaderLibrary.h"
#include "gpu/SharedStructures.h"
#include "gpu/Texture.h"

#include <string>
#include <vector>

namespace firmament {

// The tables, as the renderer reads them.
struct ScatteringTables {
    Texture2D netDensity;        // R32G32B32A32_FLOAT: (zenith cosine, altitude) -> Rayleigh, Mie, ozone net density
    Texture3D singleScattering;  // R16G16B16A16_FLOAT: L_in^(1) per unit sun irradiance, packed 4D
};

class ScatteringPrecomputation {
public:
    ScatteringPrecomputation(ID3D11Device* device, const AtmosphereParameters& parameters);

    // Runs the next unit of work; false once everything has run.
    bool step(ID3D11DeviceContext* context, ShaderLibrary& shaders);
    // Runs every remaining unit, logging progress; waits for the GPU at the end.
    void runAll(ID3D11DeviceContext* context, ShaderLibrary& shaders);

    bool done() const { return next_ >= units_.size(); }
    // The tables were filled another way (from files): nothing is left to run.
    void markComplete() { next_ = units_.size(); }
    double progress() const { return units_.empty() ? 1.0 : static_cast<double>(next_) / static_cast<double>(units_.size()); }
    std::string currentStage() const;  // "net density", "single scattering", or "done"

    const ScatteringTables& tables() const { return tables_; }
    const AtmosphereParameters& parameters() const { return parameters_; }

private:
    enum class Stage { NetDensity, SingleScattering };
    struct Unit {
        Stage stage;
        unsigned first, end;  // rows or z slices
    };
    void run(ID3D11DeviceContext* context, ShaderLibrary& shaders, const Unit& unit);

    AtmosphereParameters parameters_;
    ScatteringTables tables_;
    ConstantBuffer<gpu::AtmosphereConstants> atmosphere_;
    ConstantBuffer<gpu::PrecomputeSliceConstants> slab_;
    ComPtr<ID3D11SamplerState> linearClamp_;
    std::vector<Unit> units_;
    size_t next_ = 0;
};

// The sampler every look-up into the tables uses.
ComPtr<ID3D11SamplerState> createLinearClampSampler(ID3D11Device* device);

}  // namespace firmament
