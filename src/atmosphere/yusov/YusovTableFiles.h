#pragma once
// The atmosphere's tables as self-describing OpenEXR files, for the cache and for
// --export-luts. Each file's header says what the table is, its dimensions, how a 4D table is
// laid out in the 2D image, the parameterization and the physical constants, so that anyone can
// open it in an EXR viewer and know what they see:
//   net-density.exr        float32, x: cosine of the zenith angle (-1 .. 1), y: altitude (eq. 4)
//   single-scattering.exr  half, tiles of altitude x view zenith; tile column: sun zenith,
//                          tile row: sun-view angle
#include "atmosphere/yusov/YusovPrecomputation.h"
#include "core/ExrImage.h"

#include <filesystem>
#include <string>

namespace firmament {

// A key for everything that shapes the tables: the physical parameters and resolutions, and
// the pre-computation shaders' bytecode (an edited shader makes new tables).
std::string yusovTableKey(const AtmosphereParameters& parameters, ShaderLibrary& shaders);


// Writes every table of a complete pre-computation into `folder` as "<prefix>net-density.exr",
// "<prefix>single-scattering.exr" and the others above (through a temporary file each, so that a reader never
// sees half a file). Waits for the GPU. Throws Error.
void writeTables(ID3D11Device* device, ID3D11DeviceContext* context, const YusovPrecomputation& tables,
                           const std::string& key, const std::filesystem::path& folder, const std::string& prefix);

// Fills the tables of `tables` from files written by writeTables with the same key
// and dimensions. Returns an empty string on success, else why the files cannot be used
// ("missing" when there are none).
std::string readTables(ID3D11DeviceContext* context, YusovPrecomputation& tables, const std::string& key,
                                 const std::filesystem::path& folder, const std::string& prefix);

}  // namespace firmament
