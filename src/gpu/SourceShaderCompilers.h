#pragma once
// Picks the backend that compiles HLSL from the source folder for hot reload:
// auto (vkd3d-compiler on the host under Wine, else D3DCompile, else fxc.exe on PATH),
// or the one named by --shader-compiler.
#include "gpu/ShaderCompiler.h"

#include <filesystem>
#include <memory>
#include <optional>
#include <string_view>

namespace firmament {

enum class SourceCompilerChoice { Auto, D3DCompile, Vkd3d, Fxc, None };

std::optional<SourceCompilerChoice> parseSourceCompilerChoice(std::string_view name);  // auto|d3dcompile|vkd3d|fxc|none

// Null for None, or for Auto when no backend is present (hot reload is then off). Throws
// Error when an explicitly chosen backend cannot run here. `cacheLauncher`: the build's
// shader-cache.sh on the host (PrecompiledShaders::cacheLauncher), used by vkd3d-compiler.
std::unique_ptr<ShaderCompiler> makeSourceCompiler(SourceCompilerChoice choice, const std::filesystem::path& root,
                                                   const std::string& cacheLauncher = {});

}  // namespace firmament
