#pragma once
// Compiles HLSL from the shader source folder with a compiler program:
//  - vkd3d-compiler on the Linux host, when running under Wine (the build's compiler, so
//    reloaded shaders match the precompiled ones exactly). It takes no -D or -I, so a
//    wrapper file holds the defines and includes the source, and it runs in the shader
//    root, where #include paths start;
//  - fxc.exe from the Windows SDK, with /D and /I.
#include "gpu/ShaderCompiler.h"

#include <filesystem>

namespace firmament {

enum class ExternalCompilerKind { Vkd3dOnHost, Fxc };

class ExternalShaderCompiler final : public ShaderCompiler {
public:
    // `program`: the compiler (a host path for vkd3d, a Windows path for fxc). Throws Error
    // when the kind cannot run here (vkd3d outside Wine).
    ExternalShaderCompiler(ExternalCompilerKind kind, std::filesystem::path program, std::filesystem::path root);

    std::string name() const override;
    CompileResult compile(const ShaderKey& key) override;

private:
    ExternalCompilerKind kind_;
    std::filesystem::path program_;
    std::filesystem::path root_;
    std::filesystem::path scratch_;  // wrappers, outputs and logs of runs in flight
};

// The pieces, pure so that they are unit-tested.
std::string vkd3dWrapperSource(const ShaderKey& key);
std::string vkd3dShellCommand(const std::string& compiler, const std::string& root, const ShaderKey& key,
                              const std::string& wrapper, const std::string& output);
std::wstring fxcCommandLine(const std::filesystem::path& fxc, const std::filesystem::path& root, const ShaderKey& key,
                            const std::filesystem::path& output);

}  // namespace firmament
