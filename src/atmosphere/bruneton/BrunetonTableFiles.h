#pragma once
// Bruneton and Neyret's tables as self-describing OpenEXR files, for the cache and for
// --export-luts, beside Yusov's (YusovTableFiles):
//   bruneton-transmittance.exr  float32, x: view zenith cosine (u_mu), y: radius (u_r)
//   bruneton-irradiance.exr     float32, x: sun zenith cosine, y: radius
//   bruneton-inscatter.exr      half, the 3D texture's layers stacked: x nu slice * N_mu_s + mu_s,
//                               y radius layer * N_mu + mu; the light times kBrunetonInscatterScale
// Each header holds the key, the dimensions, the layout, the parameterization, the ground
// albedo and the physical constants.
#include "atmosphere/bruneton/BrunetonPrecomputation.h"

#include <filesystem>
#include <string>

namespace firmament {

// Writes the three tables of a complete pre-computation as "<prefix>bruneton-*.exr". Throws Error.
void writeTables(ID3D11Device* device, ID3D11DeviceContext* context, const BrunetonPrecomputation& tables,
                           const std::string& key, const std::filesystem::path& folder, const std::string& prefix);

// Fills the tables from files of the same key and sizes, and marks the pre-computation done.
// An empty string on success, else why the files cannot be used ("missing" when there are none).
std::string readTables(ID3D11DeviceContext* context, BrunetonPrecomputation& tables, const std::string& key,
                                 const std::filesystem::path& folder, const std::string& prefix);

}  // namespace firmament
