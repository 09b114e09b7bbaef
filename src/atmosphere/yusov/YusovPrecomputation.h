#pragma once
// Fills the atmosphere's look-up tables on the GPU (Yusov 2013, frame order step 1):
//   1. net density to the top of the atmosphere, 2D (precompute_net_density.hlsl);
//   2. single scattering L^(1), 4D packed into 3D, each species without its phase function
//      (precompute_single_scattering.hlsl);
//   3. for each order n = 2..N: J^(n) over the sphere, then L^(n) along the view rays and the
//      high-order sum L^H (precompute_multiple_scattering.hlsl);
//   4. the multiple scattering table L^M = L^(1) + L^H, by species like L^(1);
//   5. the ambient sky light, 1D (precompute_ambient_light.hlsl).
// The work is cut into units (blocks of rows, slabs of z slices) of a fraction of a second each
// on the WARP device, so that a recompute can run one unit per frame and the window stays
// responsive; runAll() does everything at once, with progress in the log.
#include "atmosphere/AtmosphereComputeInputs.h"
#include "atmosphere/AtmosphereParameters.h"
#include "gpu/ShaderLibrary.h"
#include "gpu/Texture.h"
#include "tables/StagedComputation.h"

#include <span>
#include <string>

namespace firmament {

// The 4D tables hold their light times this (half floats would round the light of deep twilight
// away; shaders/atmosphere/yusov/lookup.hlsli's kTableScale, the same number, says more).
constexpr double kYusovTableScale = 1e4;

// The tables, as the renderer reads them.
struct YusovTables {
    Texture2D netDensity;           // R32G32B32A32_FLOAT: (zenith cosine, altitude) -> Rayleigh, Mie, ozone net density
    Texture3D singleScattering;     // R16G16B16A16_FLOAT: L^(1) per unit sun irradiance times kYusovTableScale, packed 4D, by species: S_R in
                                    //   altitude texels [0, N), S_M in [N, 2N), without their phases
    Texture3D highOrderScattering;  //   L^H = L^(2) + ... + L^(N), radiance
    Texture3D multipleScattering;   //   L^M = L^(1) + L^H by species: S_R + L^H / P_R, then S_M
    Texture2D ambientLight;         // R16G16B16A16_FLOAT, N x 1: sky irradiance on the ground per unit sun irradiance
};

enum class YusovStage { NetDensity, SingleScattering, ScatteredRadiance, ScatteringOrder, Combine, AmbientLight };
// For the log: a stage's name, and the tables' sizes and orders.
std::string stageName(YusovStage stage, int order);
std::string describeTables(const AtmosphereParameters& parameters);
// Every compute shader of the pre-computation (the tables' cache key hashes their bytecode).
std::span<const ShaderKey> yusovPrecomputeShaders();

// What only computing needs: the shaders' inputs, J^(n) (float32: it is too small for half),
// the orders n - 1 and n, and the high-order sums before and after order n (ping-pong: UAVs of
// RGBA16F cannot be read and written in place; one of the two is the high-order table itself).
struct YusovScratch {
    YusovScratch(ID3D11Device* device, const AtmosphereParameters& parameters, const YusovTables& tables);
    AtmosphereComputeInputs inputs;
    Texture3D scattered;
    Texture3D orders[2];
    Texture3D highOrders[2];
};

class YusovPrecomputation final : public StagedComputation<YusovStage, AtmosphereParameters, YusovTables, YusovScratch> {
public:
    YusovPrecomputation(ID3D11Device* device, const AtmosphereParameters& parameters);
};

}  // namespace firmament
