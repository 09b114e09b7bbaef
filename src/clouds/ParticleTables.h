#pragma once
// The cloud particle's pre-computed tables (Yusov 2014, frame order step 1), computed on the GPU
// in units of work and cached with the atmosphere's table machinery (src/tables/): today the
// optical depth table, 4D packed into 3D (precompute_optical_depth.hlsl), for the chosen
// particle density method.
#include "clouds/CloudSettings.h"
#include "clouds/CloudStructures.h"
#include "clouds/OpticalDepthTable.h"
#include "gpu/ConstantBuffer.h"
#include "gpu/ShaderLibrary.h"
#include "gpu/Texture.h"
#include "tables/StagedComputation.h"

#include <d3d11.h>

#include <filesystem>
#include <span>
#include <string>

namespace firmament {

struct ParticleTableParameters {
    ParticleDensityMethod method = ParticleDensityMethod::RadialNoise;
    OpticalDepthTableSize opticalDepth;

    std::string describe() const;  // everything that shapes the tables, for the cache key
};

struct ParticleTables {
    Texture3D opticalDepth;  // R32_FLOAT: the mean density along a chord of the unit sphere (optical_depth_table.hlsli)
};

enum class ParticleTableStage { OpticalDepth };
std::string stageName(ParticleTableStage stage, int order);
std::string describeTables(const ParticleTableParameters& parameters);
std::span<const ShaderKey> particleTableShaders();

// What only computing needs: the shader's constants.
struct ParticleTableScratch {
    ParticleTableScratch(ID3D11Device* device, const ParticleTableParameters& parameters, const ParticleTables& tables);
    ConstantBuffer<gpu::ParticleTableConstants> constants;
};

class ParticleTablePrecomputation final
    : public StagedComputation<ParticleTableStage, ParticleTableParameters, ParticleTables, ParticleTableScratch> {
public:
    ParticleTablePrecomputation(ID3D11Device* device, const ParticleTableParameters& parameters);
};

// The cache key, and the tables' files in the cache (CachedTables' overloads).
std::string particleTableKey(const ParticleTableParameters& parameters, ShaderLibrary& shaders);
void writeTables(ID3D11Device* device, ID3D11DeviceContext* context, const ParticleTablePrecomputation& tables, const std::string& key,
                 const std::filesystem::path& folder, const std::string& prefix);
std::string readTables(ID3D11DeviceContext* context, ParticleTablePrecomputation& tables, const std::string& key, const std::filesystem::path& folder,
                       const std::string& prefix);

}  // namespace firmament
