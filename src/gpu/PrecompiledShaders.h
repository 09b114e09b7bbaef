#pragma once
// The DXBC the build compiled: a folder of .cso files and manifest.txt mapping each
// permutation's key to its file ("key<TAB>file" lines).
#include "gpu/ShaderCompiler.h"

#include <filesystem>
#include <map>
#include <optional>

namespace firmament {

class PrecompiledShaders final : public ShaderCompiler {
public:
    explicit PrecompiledShaders(std::filesystem::path folder);  // throws Error if the folder or manifest is missing

    std::string name() const override { return "precompiled (" + folder_.string() + ")"; }
    CompileResult compile(const ShaderKey& key) override;

    const std::filesystem::path& folder() const { return folder_; }
    size_t size() const { return files_.size(); }
    // The HLSL folder these were compiled from (the manifest's "#source" line), for hot reload.
    const std::optional<std::filesystem::path>& sourceRoot() const { return sourceRoot_; }
    // The build's compiled-shader cache launcher (the manifest's "#cache" line, a host path),
    // empty when the build used none.
    const std::string& cacheLauncher() const { return cacheLauncher_; }

private:
    std::filesystem::path folder_;
    std::map<std::string, std::string> files_;  // key id -> .cso file name
    std::optional<std::filesystem::path> sourceRoot_;
    std::string cacheLauncher_;
};

}  // namespace firmament
