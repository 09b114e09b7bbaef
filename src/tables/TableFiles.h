#pragma once
// Tables cached on disk as OpenEXR files: the cache key of tables made on the GPU, which hashes
// the pre-computation shaders' bytecode too. The header check and the CPU-only key are in
// tables/TableFileHeaders.h.
#include "core/ExrImage.h"
#include "gpu/Readback.h"
#include "gpu/ShaderLibrary.h"
#include "tables/TableFileHeaders.h"

#include <span>
#include <string>

namespace firmament {

// A key for everything that shapes a set of tables: the 64-bit FNV-1a hash of their
// description and of the pre-computation shaders' bytecode (an edited shader makes new
// tables), in hex.
std::string tableKey(const std::string& description, ShaderLibrary& shaders, std::span<const ShaderKey> precomputeShaders);

// A float32 RGBA texture read back, as an image for writeExr.
FloatRgbaImage floatRgbaImage(const ReadbackImage& texels);

}  // namespace firmament
