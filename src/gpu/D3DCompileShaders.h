#pragma once
// Compiles HLSL from the shader source folder with D3DCompile from d3dcompiler_47.dll (loaded
// at run time). The default hot-reload backend on Windows. Wine has its own d3dcompiler_47,
// which compiles simple shaders but not all of ours (see docs/building.md).
#include "gpu/ShaderCompiler.h"

#include <windows.h>

#include <filesystem>

namespace firmament {

class D3DCompileShaders final : public ShaderCompiler {
public:
    explicit D3DCompileShaders(std::filesystem::path root);  // throws Error if the DLL is missing
    ~D3DCompileShaders() override;
    D3DCompileShaders(const D3DCompileShaders&) = delete;
    D3DCompileShaders& operator=(const D3DCompileShaders&) = delete;

    static bool available();

    std::string name() const override { return "D3DCompile (d3dcompiler_47.dll)"; }
    CompileResult compile(const ShaderKey& key) override;

private:
    std::filesystem::path root_;
    HMODULE library_ = nullptr;
    void* compile_ = nullptr;  // D3DCompile
};

}  // namespace firmament
