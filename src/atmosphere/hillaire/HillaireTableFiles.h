#pragma once
// Hillaire 2020's camera-independent tables as self-describing OpenEXR files, for the cache and
// for --export-luts, beside the other models' (YusovTableFiles, BrunetonTableFiles), all float32:
//   hillaire-transmittance.exr        x: u_mu, y: u_r (Bruneton 2017's mapping)
//   hillaire-multiple-scattering.exr  x: 0.5 + 0.5 mu_s, y: (r - Rg) / (Rt - Rg)
//   hillaire-irradiance.exr           the same mapping as the multiple scattering
// Each header holds the key, the dimensions, the layout, the parameterization, the sampling and
// the physical constants. The sky-view table and the aerial-perspective volume follow the camera
// and are not stored.
#include "atmosphere/hillaire/HillairePrecomputation.h"

#include <filesystem>
#include <string>

namespace firmament {

// Writes the three tables of a complete pre-computation as "<prefix>hillaire-*.exr". Throws Error.
void writeTables(ID3D11Device* device, ID3D11DeviceContext* context, const HillairePrecomputation& tables, const std::string& key,
                 const std::filesystem::path& folder, const std::string& prefix);

// Fills the tables from files of the same key and sizes, and marks the pre-computation done.
// An empty string on success, else why the files cannot be used ("missing" when there are none).
std::string readTables(ID3D11DeviceContext* context, HillairePrecomputation& tables, const std::string& key, const std::filesystem::path& folder,
                       const std::string& prefix);

}  // namespace firmament
