#pragma once
// Fills the atmosphere's look-up tables on the GPU (document 000, frame order step 1):
//   1. net density to the top of the atmosphere, 2D (precompute_net_density.hlsl);
//   2. single scattering L^(1), 4D packed into 3D (precompute_single_scattering.hlsl);
//   3. for each order n = 2..N: J^(n) over the sphere, then L^(n) along the view rays and the
//      high-order sum L^H (precompute_multiple_scattering.hlsl);
//   4. the multiple scattering table L^M = L^(1) + L^H;
//   5. the ambient sky light, 1D (precompute_ambient_light.hlsl).
// The work is cut into units (blocks of rows, slabs of z slices) of a fraction of a second each
// on the WARP device, so that a recompute can run one unit per frame and the window stays
// responsive; runAll() does everything at once, with progress in the log.
#include "atmosphere/AtmosphereParameters.h"
#include "atmosphere/PrecomputationSupport.h"
#include "gpu/ConstantBuffer.h"
#include "gpu/ShaderLibrary.h"
#include "gpu/SharedStructures.h"
#include "gpu/Texture.h"

#include <string>
#include <vector>

namespace firmament {

// The tables, as the renderer reads them.
struct ScatteringTables {
    Texture2D netDensity;           // R32G32B32A32_FLOAT: (zenith cosine, altitude) -> Rayleigh, Mie, ozone net density
    Texture3D singleScattering;     // R16G16B16A16_FLOAT: L^(1) per unit sun irradiance, packed 4D
    Texture3D highOrderScattering;  //   L^H = L^(2) + ... + L^(N)
    Texture3D multipleScattering;   //   L^M = L^(1) + L^H
    Texture2D ambientLight;         // R16G16B16A16_FLOAT, N x 1: sky irradiance on the ground per unit sun irradiance
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
    void markComplete();
    double progress() const { return units_.empty() ? 1.0 : static_cast<double>(next_) / static_cast<double>(units_.size()); }
    std::string currentStage() const;

    const ScatteringTables& tables() const { return tables_; }
    const AtmosphereParameters& parameters() const { return parameters_; }

private:
    enum class Stage { NetDensity, SingleScattering, ScatteredRadiance, ScatteringOrder, Combine, AmbientLight };
    struct Unit {
        Stage stage;
        unsigned first, end;  // rows or z slices
        int order;            // n, for the multiple scattering stages
    };
    void run(ID3D11DeviceContext* context, ShaderLibrary& shaders, const Unit& unit);
    void allocateScratch();
    void releaseScratch();

    ID3D11Device* device_;
    AtmosphereParameters parameters_;
    ScatteringTables tables_;
    // Only while computing (made by the first step, released by the last): J^(n) (float32: it
    // is too small for half), the orders n - 1 and n, and the high-order sums before and after
    // order n (ping-pong: UAVs of RGBA16F cannot be read and written in place; one of the two
    // is the high-order table itself).
    Texture3D scattered_;
    Texture3D orders_[2];
    Texture3D highOrders_[2];
    ComPtr<ID3D11ShaderResourceView> sphereDirectionsView_;
    ConstantBuffer<gpu::AtmosphereConstants> atmosphere_;
    ConstantBuffer<gpu::PrecomputeSliceConstants> slab_;
    ComPtr<ID3D11SamplerState> linearClamp_;
    std::vector<Unit> units_;
    size_t next_ = 0;
};

}  // namespace firmament
